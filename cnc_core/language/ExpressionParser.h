#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "cnc_core/language/Lexer.h"
#include "cnc_core/language/Program.h"

namespace mtc::core {

/// Recursive-descent parser for NC arithmetic: + - * / with the usual
/// precedence, unary minus, parentheses, constants, variables @n / @p:n and
/// the reads M(n), G(n), T, E, S, S1..S3, SPC, TIME, MTD(a,b,c,d).
///
/// Blanks: inside parentheses they are free. At the outer level an
/// expression ends at a blank unless the next non-blank character is a binary
/// operator ("@1=@2 + 3" is one expression, "@1=@2 @3=4" two assignments).
class ExpressionParser {
  public:
    /// Nesting deeper than this is a diagnostic, not a stack overflow.
    static constexpr int kMaxDepth = 64;
    /// Most nodes one expression may have (keeps evaluation recursion bounded).
    static constexpr std::size_t kMaxNodes = 1024;

    struct Error {
        const char* code = nullptr;
        std::uint32_t offset = 0;
        std::string message;
    };

    ExpressionParser(Lexer& lexer, std::vector<ExprNode>& nodes, std::string_view source)
        : lexer_(lexer), nodes_(nodes), source_(source), nodeLimit_(nodes.size() + kMaxNodes) {}

    /// Parses an expression at the lexer position and appends its nodes.
    /// Returns the root node index, or -1 with error() set (nodes appended
    /// before the error stay; the caller truncates).
    std::int32_t parse();
    /// Parses "@n" or "@p:n" at the lexer position (at '@').
    std::int32_t parseVariable();
    /// Parses "(a,b,c,d)" after MTD (lexer at the blank or '(') into a
    /// ReadMTD node. Empty arguments are -1; with three arguments the third
    /// is the element (d), with two the second is.
    std::int32_t parseAxdRead(std::uint32_t offset);
    std::int32_t parseMtdArguments(std::uint32_t keywordOffset, int depth = 0);
    const Error& error() const { return error_; }

  private:
    std::int32_t parseSum(int depth, bool nested);
    std::int32_t parseProduct(int depth, bool nested);
    std::int32_t parseUnary(int depth, bool nested);
    std::int32_t parsePrimary(int depth, bool nested);
    std::int32_t parseRead(std::string_view name, std::uint32_t offset, int depth);
    std::int32_t parseParenthesized(ExprOp op, std::uint32_t offset, int depth);
    /// Peeks the next binary operator of `level` (0: + -, 1: * /); consumes
    /// blanks before it only where allowed. Returns 0 when none.
    char peekOperator(int level, bool nested);
    std::int32_t add(ExprNode node);
    std::int32_t fail(const char* code, std::uint32_t offset, std::string message);

    Lexer& lexer_;
    std::vector<ExprNode>& nodes_;
    std::string_view source_;
    Error error_;
    std::size_t nodeLimit_ = 0;
};

}  // namespace mtc::core
