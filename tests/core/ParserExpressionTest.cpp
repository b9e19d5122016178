// Arithmetic, reads and MTD in NC expressions.
#include <gtest/gtest.h>

#include "ParserTestSupport.h"

using namespace mtc::core;
using namespace mtc::core::testing;

namespace {

/// The value expression of the first word of `line` ("@1=<expr>").
std::string value(const std::string& expression) {
    Program p = parse("@1=" + expression);
    EXPECT_TRUE(p.diagnostics.empty())
        << expression << " -> "
        << (p.diagnostics.empty() ? "" : formatDiagnostic(p.diagnostics.items()[0]));
    if (p.words.empty()) return "";
    return describeValue(p, p.words[0]);
}

TEST(ParserExpression, Precedence) {
    EXPECT_EQ(value("1+2*3"), "1+(2*3)");
    EXPECT_EQ(value("(1+2)*3"), "(1+2)*3");
    EXPECT_EQ(value("8/4/2"), "(8/4)/2");
    EXPECT_EQ(value("10-4-3"), "(10-4)-3");
}

TEST(ParserExpression, UnaryMinus) {
    EXPECT_EQ(value("-@5"), "-@5");
    EXPECT_EQ(value("-(@1+2)"), "-(@1+2)");
    EXPECT_EQ(value("@1*-2"), "@1*-2");
}

TEST(ParserExpression, ConstantsAreFolded) {
    Program p = parse("@1=-7.5");
    EXPECT_EQ(p.words[0].expr, -1);
    EXPECT_EQ(p.words[0].number, -7.5);
    EXPECT_EQ(p.expressions.size(), 1u);  // only the target variable
}

TEST(ParserExpression, Variables) {
    EXPECT_EQ(value("@100+@1:120"), "@100+@1:120");
    Program p = parse("@7=@2:15");
    const ExprNode& read = p.expressions[static_cast<std::size_t>(p.words[0].expr)];
    EXPECT_EQ(read.op, ExprOp::Variable);
    EXPECT_EQ(read.process, 2);
    EXPECT_EQ(read.index, 15);
    const ExprNode& target = p.expressions[static_cast<std::size_t>(p.words[0].target)];
    EXPECT_EQ(target.process, -1);
    EXPECT_EQ(target.index, 7);
}

TEST(ParserExpression, Reads) {
    EXPECT_EQ(value("M(5)-1"), "M(5)-1");
    EXPECT_EQ(value("G(2)-18"), "G(2)-18");
    EXPECT_EQ(value("T"), "T");
    EXPECT_EQ(value("E"), "E");
    EXPECT_EQ(value("S"), "S");
    EXPECT_EQ(value("S2"), "S2");
    EXPECT_EQ(value("SPC-1"), "SPC-1");
    EXPECT_EQ(value("TIME"), "TIME");
    EXPECT_EQ(value("M(@3)"), "M(@3)");
}

TEST(ParserExpression, MtdArgumentForms) {
    EXPECT_EQ(value("MTD(61, 0, 1, @100)-0"), "MTD(61,0,1,@100)-0");
    EXPECT_EQ(value("MTD(60,,,5)"), "MTD(60,,,5)");
    EXPECT_EQ(value("MTD(61,,1,@100)"), "MTD(61,,1,@100)");
    // Three arguments: the third is the element.
    EXPECT_EQ(value("MTD(60,,4)-32"), "MTD(60,,,4)-32");
    EXPECT_EQ(value("MTD(60,5)"), "MTD(60,,,5)");
    EXPECT_EQ(value("MTD (112, 1, 8, 1)"), "MTD(112,1,8,1)");
    EXPECT_EQ(value("MTD(60,,,1)+MTD(60,,,2)"), "MTD(60,,,1)+MTD(60,,,2)");
}

TEST(ParserExpression, BlanksInsideParenthesesAndAroundOperators) {
    EXPECT_EQ(value("( @1 + 2 ) * 3"), "(@1+2)*3");
    EXPECT_EQ(value("@2 + 3"), "@2+3");
    EXPECT_EQ(value("@2 /2"), "@2/2");
}

TEST(ParserExpression, BlankEndsTheExpressionBeforeTheNextWord) {
    Program p = parse("@100=M(5)-1 BMI .INI");
    ASSERT_TRUE(p.diagnostics.empty());
    EXPECT_EQ(describeBlock(p, 0), "@100=M(5)-1 BMI .INI");
    Program q = parse("@1=@2 @3=4");
    EXPECT_EQ(describeBlock(q, 0), "@1=@2 @3=4");
}

TEST(ParserExpression, ChildrenPrecedeTheirParent) {
    Program p = parse("@1=(@2+3)*MTD(60,,@4,5)-M(G(1))");
    ASSERT_TRUE(p.diagnostics.empty());
    for (std::size_t i = 0; i < p.expressions.size(); ++i) {
        const ExprNode& n = p.expressions[i];
        for (std::int32_t child : {n.a, n.b, n.c, n.d})
            EXPECT_LT(child, static_cast<std::int32_t>(i)) << "node " << i;
    }
}

TEST(ParserExpression, NestingLimitIsADiagnostic) {
    std::string deep = "@1=" + std::string(100, '(') + "1" + std::string(100, ')');
    Program p = parse(deep);
    ASSERT_NE(find(p, "PARSE_EXPRESSION_TOO_DEEP"), nullptr);
    std::string minus = "@1=" + std::string(200, '-') + "1";
    EXPECT_NE(find(parse(minus), "PARSE_EXPRESSION_TOO_DEEP"), nullptr);
    std::string mtd = "@1=";
    for (int i = 0; i < 80; ++i)
        mtd += "MTD(1,";
    mtd += "1" + std::string(80, ')');
    EXPECT_NE(find(parse(mtd), "PARSE_EXPRESSION_TOO_DEEP"), nullptr);
}

TEST(ParserExpression, TermLimitIsADiagnostic) {
    std::string chain = "@1=1";
    for (int i = 0; i < 2000; ++i)
        chain += "+1";
    Program p = parse(chain);
    EXPECT_NE(find(p, "PARSE_EXPRESSION_TOO_LONG"), nullptr);
    EXPECT_TRUE(p.expressions.empty());  // the failed block leaves no nodes behind
}

TEST(ParserExpression, Errors) {
    EXPECT_NE(find(parse("@1=M5"), "PARSE_BAD_EXPRESSION"), nullptr);
    EXPECT_NE(find(parse("@1=X"), "PARSE_BAD_EXPRESSION"), nullptr);
    EXPECT_NE(find(parse("@1=(2+3"), "PARSE_UNBALANCED_PARENTHESES"), nullptr);
    EXPECT_NE(find(parse("@1="), "PARSE_MISSING_VALUE"), nullptr);
    EXPECT_NE(find(parse("@1=2+"), "PARSE_MISSING_VALUE"), nullptr);
    EXPECT_NE(find(parse("@1=MTD(60)"), "PARSE_BAD_MTD"), nullptr);
    EXPECT_NE(find(parse("@1=MTD(1,2,3,4,5)"), "PARSE_BAD_MTD"), nullptr);
    EXPECT_NE(find(parse("@1=MTD 60"), "PARSE_BAD_MTD"), nullptr);
    EXPECT_NE(find(parse("@1=MTD(60,,3"), "PARSE_UNBALANCED_PARENTHESES"), nullptr);
    EXPECT_NE(find(parse("@1=S12"), "PARSE_BAD_EXPRESSION"), nullptr);
    EXPECT_NE(find(parse("@1=1.2.3"), "PARSE_BAD_NUMBER"), nullptr);
    EXPECT_NE(find(parse("@=3"), "PARSE_BAD_VARIABLE"), nullptr);
    EXPECT_NE(find(parse("@1.5=3"), "PARSE_BAD_VARIABLE"), nullptr);
    EXPECT_NE(find(parse("@200:1=3"), "PARSE_BAD_VARIABLE"), nullptr);
    EXPECT_NE(find(parse("@99999999999=3"), "PARSE_BAD_VARIABLE"), nullptr);
    EXPECT_NE(find(parse("@1 5"), "PARSE_EXPECTED_ASSIGNMENT"), nullptr);
    EXPECT_NE(find(parse("MTD(1,,,2)"), "PARSE_EXPECTED_ASSIGNMENT"), nullptr);
}

}  // namespace
