#include "cnc_core/language/ExpressionParser.h"

#include <cmath>

namespace mtc::core {

std::int32_t ExpressionParser::add(ExprNode node) {
    if (nodes_.size() >= nodeLimit_)
        return fail("PARSE_EXPRESSION_TOO_LONG", lexer_.position(),
                    "expression has more than 1024 terms");
    nodes_.push_back(node);
    return static_cast<std::int32_t>(nodes_.size() - 1);
}

std::int32_t ExpressionParser::fail(const char* code, std::uint32_t offset, std::string message) {
    if (error_.code == nullptr) error_ = Error{code, offset, std::move(message)};
    return -1;
}

std::int32_t ExpressionParser::parse() {
    nodeLimit_ = nodes_.size() + kMaxNodes;
    lexer_.skipBlanks();
    return parseSum(0, false);
}

char ExpressionParser::peekOperator(int level, bool nested) {
    std::uint32_t save = lexer_.position();
    lexer_.skipBlanks();
    int c = lexer_.peek();
    bool match = level == 0 ? (c == '+' || c == '-') : (c == '*' || c == '/');
    if (!match) {
        // Blanks before a non-operator: leave them (outer level) or keep
        // them skipped (inside parentheses nothing else may follow anyway).
        if (!nested) lexer_.seek(save);
        return 0;
    }
    return static_cast<char>(c);
}

std::int32_t ExpressionParser::parseSum(int depth, bool nested) {
    std::int32_t left = parseProduct(depth, nested);
    while (left >= 0) {
        char op = peekOperator(0, nested);
        if (op == 0) break;
        lexer_.advance();
        lexer_.skipBlanks();
        std::int32_t right = parseProduct(depth, nested);
        if (right < 0) return -1;
        ExprNode node;
        node.op = op == '+' ? ExprOp::Add : ExprOp::Subtract;
        node.a = left;
        node.b = right;
        left = add(node);
    }
    return left;
}

std::int32_t ExpressionParser::parseProduct(int depth, bool nested) {
    std::int32_t left = parseUnary(depth, nested);
    while (left >= 0) {
        char op = peekOperator(1, nested);
        if (op == 0) break;
        lexer_.advance();
        lexer_.skipBlanks();
        std::int32_t right = parseUnary(depth, nested);
        if (right < 0) return -1;
        ExprNode node;
        node.op = op == '*' ? ExprOp::Multiply : ExprOp::Divide;
        node.a = left;
        node.b = right;
        left = add(node);
    }
    return left;
}

std::int32_t ExpressionParser::parseUnary(int depth, bool nested) {
    if (depth > kMaxDepth)
        return fail("PARSE_EXPRESSION_TOO_DEEP", lexer_.position(),
                    "expression nested deeper than 64 levels");
    int c = lexer_.peek();
    if (c == '-' || c == '+') {
        lexer_.advance();
        lexer_.skipBlanks();
        std::int32_t operand = parseUnary(depth + 1, nested);
        if (operand < 0 || c == '+') return operand;
        ExprNode node;
        node.op = ExprOp::Negate;
        node.a = operand;
        return add(node);
    }
    return parsePrimary(depth, nested);
}

std::int32_t ExpressionParser::parsePrimary(int depth, bool nested) {
    (void)nested;
    std::uint32_t offset = lexer_.position();
    int c = lexer_.peek();
    NumberText number;
    if ((Lexer::isDigit(c) || c == '.') && lexer_.scanNumber(number)) {
        if (lexer_.peek() == '.')
            return fail("PARSE_BAD_NUMBER", lexer_.position(), "number with two decimal points");
        ExprNode node;
        node.value = number.value(source_);
        if (!std::isfinite(node.value))
            return fail("PARSE_BAD_NUMBER", offset, "number out of range");
        return add(node);
    }
    if (c == '@') return parseVariable();
    if (c == '(') return parseParenthesized(ExprOp::Constant, offset, depth);
    if (Lexer::isUpper(c)) return parseRead(lexer_.scanIdentifier(), offset, depth);
    if (c < 0) return fail("PARSE_MISSING_VALUE", offset, "expression expected");
    return fail("PARSE_BAD_EXPRESSION", offset,
                std::string("unexpected character '") + static_cast<char>(c) + "' in expression");
}

std::int32_t ExpressionParser::parseParenthesized(ExprOp op, std::uint32_t offset, int depth) {
    // op == Constant: plain grouping; ReadM / ReadG: one argument.
    if (lexer_.peek() != '(')
        return fail("PARSE_BAD_EXPRESSION", lexer_.position(), "'(' expected");
    lexer_.advance();
    lexer_.skipBlanks();
    std::int32_t inner = parseSum(depth + 1, true);
    if (inner < 0) return -1;
    lexer_.skipBlanks();
    if (lexer_.peek() != ')') return fail("PARSE_UNBALANCED_PARENTHESES", offset, "')' missing");
    lexer_.advance();
    if (op == ExprOp::Constant) return inner;
    ExprNode node;
    node.op = op;
    node.a = inner;
    return add(node);
}

std::int32_t ExpressionParser::parseRead(std::string_view name, std::uint32_t offset, int depth) {
    ExprNode node;
    if (name == "M" || name == "G") {
        lexer_.skipBlanks();
        return parseParenthesized(name == "M" ? ExprOp::ReadM : ExprOp::ReadG, offset, depth);
    }
    if (name == "MTD") return parseMtdArguments(offset, depth + 1);
    if (name == "AXD") return parseAxdRead(offset);
    if (name == "T") {
        node.op = ExprOp::ReadT;
    } else if (name == "E") {
        node.op = ExprOp::ReadE;
    } else if (name == "Q") {
        node.op = ExprOp::ReadQ;
    } else if (name == "SPC") {
        node.op = ExprOp::ReadSPC;
    } else if (name == "TIME") {
        node.op = ExprOp::ReadTime;
    } else if (name == "S") {
        node.op = ExprOp::ReadS;
        int c = lexer_.peek();
        if (c >= '1' && c <= '3' && !Lexer::isDigit(lexer_.peek(1)) && lexer_.peek(1) != '.') {
            node.index = c - '0';
            lexer_.advance();
        }
    } else {
        return fail("PARSE_BAD_EXPRESSION", offset,
                    "'" + std::string(name) + "' cannot be read in an expression");
    }
    if (Lexer::isDigit(lexer_.peek()) || lexer_.peek() == '.')
        return fail("PARSE_BAD_EXPRESSION", lexer_.position(),
                    "number directly after '" + std::string(name) + "' in an expression");
    return add(node);
}

std::int32_t ExpressionParser::parseAxdRead(std::uint32_t offset) {
    // AXD(X:P-7-3652): axis designation (X..C, S, S1..S3), ':', P-7-<number>.
    lexer_.skipBlanks();
    if (lexer_.peek() != '(') return fail("PARSE_BAD_AXD", offset, "AXD needs (axis:parameter)");
    lexer_.advance();
    lexer_.skipBlanks();
    const int letter = lexer_.peek();
    if (!Lexer::isUpper(letter))
        return fail("PARSE_BAD_AXD", offset, "AXD: axis designation expected");
    lexer_.advance();
    int axisIndex = 0;
    if (Lexer::isDigit(lexer_.peek())) {
        axisIndex = lexer_.peek() - '0';
        lexer_.advance();
    }
    if (letter == 'S' && axisIndex == 0) axisIndex = 1;
    lexer_.skipBlanks();
    const std::string_view prefix = "P-7-";
    bool ok = lexer_.peek() == ':';
    lexer_.advance();
    lexer_.skipBlanks();
    for (std::size_t i = 0; ok && i < prefix.size(); ++i, lexer_.advance())
        ok = lexer_.peek() == prefix[i];
    int number = 0, digits = 0;
    for (; ok && Lexer::isDigit(lexer_.peek()) && digits < 6; ++digits, lexer_.advance())
        number = number * 10 + (lexer_.peek() - '0');
    lexer_.skipBlanks();
    if (!ok || digits == 0 || lexer_.peek() != ')')
        return fail("PARSE_BAD_AXD", offset, "AXD is read as AXD(axis:P-7-nnnn)");
    lexer_.advance();
    ExprNode node;
    node.op = ExprOp::ReadAXD;
    node.index = letter * 10 + axisIndex;
    node.value = number;
    return add(node);
}

std::int32_t ExpressionParser::parseVariable() {
    std::uint32_t offset = lexer_.position();
    lexer_.advance();  // '@'
    NumberText first;
    if (!Lexer::isDigit(lexer_.peek()) || !lexer_.scanNumber(first) || first.scale != 0 ||
        source_[first.end - 1] == '.')
        return fail("PARSE_BAD_VARIABLE", offset, "'@' must be followed by a variable number");
    ExprNode node;
    node.op = ExprOp::Variable;
    std::int64_t number = first.exact ? first.mantissa : -1;
    if (lexer_.peek() == ':' && Lexer::isDigit(lexer_.peek(1))) {
        lexer_.advance();
        NumberText second;
        lexer_.scanNumber(second);
        if (number < 0 || number > 127 || second.scale != 0 || !second.exact)
            return fail("PARSE_BAD_VARIABLE", offset, "bad process number in @p:n");
        node.process = static_cast<std::int8_t>(number);
        number = second.mantissa;
    }
    if (number < 0 || number > 2147483647)
        return fail("PARSE_BAD_VARIABLE", offset, "variable number out of range");
    node.index = static_cast<std::int32_t>(number);
    return add(node);
}

std::int32_t ExpressionParser::parseMtdArguments(std::uint32_t keywordOffset, int depth) {
    if (depth > kMaxDepth)
        return fail("PARSE_EXPRESSION_TOO_DEEP", keywordOffset,
                    "expression nested deeper than 64 levels");
    lexer_.skipBlanks();
    if (lexer_.peek() != '(')
        return fail("PARSE_BAD_MTD", lexer_.position(), "MTD needs its arguments in ( )");
    lexer_.advance();
    std::int32_t args[4] = {-1, -1, -1, -1};
    int count = 0;
    for (;;) {
        lexer_.skipBlanks();
        int c = lexer_.peek();
        if (count == 4)
            return fail("PARSE_BAD_MTD", keywordOffset, "MTD takes at most 4 arguments");
        if (c != ',' && c != ')') {
            args[count] = parseSum(depth + 1, true);
            if (args[count] < 0) return -1;
            lexer_.skipBlanks();
            c = lexer_.peek();
        }
        ++count;
        if (c == ')') break;
        if (c != ',')
            return fail("PARSE_UNBALANCED_PARENTHESES", keywordOffset, "MTD: ',' or ')' expected");
        lexer_.advance();
    }
    lexer_.advance();  // ')'
    if (count < 2) return fail("PARSE_BAD_MTD", keywordOffset, "MTD needs at least 2 arguments");
    if (count < 4) {  // the last argument is the element
        args[3] = args[count - 1];
        args[count - 1] = -1;
    }
    ExprNode node;
    node.op = ExprOp::ReadMTD;
    node.a = args[0];
    node.b = args[1];
    node.c = args[2];
    node.d = args[3];
    return add(node);
}

}  // namespace mtc::core
