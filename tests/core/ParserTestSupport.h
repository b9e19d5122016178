#pragma once

// Helpers for the language tests: parse a text and describe blocks, words
// and expressions as short strings ("G1 X12.345 Y1=25 @100=M(5)-1 BRA .L").

#include <cstdio>
#include <string>
#include <vector>

#include "cnc_core/language/Keywords.h"
#include "cnc_core/language/Parser.h"

namespace mtc::core::testing {

inline Program parse(const std::string& text, int number = 0) {
    ParseOptions options;
    options.programNumber = number;
    return parseProgram(text, options);
}

inline std::string formatNumber(double value) {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%.10g", value);
    return buffer;
}

inline std::string describeExpr(const Program& p, std::int32_t index);

inline std::string describeOperand(const Program& p, std::int32_t index) {
    if (index < 0) return "";
    ExprOp op = p.expressions[static_cast<std::size_t>(index)].op;
    bool binary = op == ExprOp::Add || op == ExprOp::Subtract || op == ExprOp::Multiply ||
                  op == ExprOp::Divide;
    return binary ? "(" + describeExpr(p, index) + ")" : describeExpr(p, index);
}

/// Renders an expression; binary children in parentheses except a sum's
/// left operand ("M(5)-1", "(@1+2)*3", "@1+2+3" -> "(@1+2)+3").
inline std::string describeExpr(const Program& p, std::int32_t index) {
    if (index < 0) return "";
    const ExprNode& n = p.expressions[static_cast<std::size_t>(index)];
    switch (n.op) {
        case ExprOp::Constant:
            return formatNumber(n.value);
        case ExprOp::Variable:
            return "@" + (n.process >= 0 ? std::to_string(n.process) + ":" : "") +
                   std::to_string(n.index);
        case ExprOp::Negate:
            return "-" + describeOperand(p, n.a);
        case ExprOp::Add:
            return describeOperand(p, n.a) + "+" + describeOperand(p, n.b);
        case ExprOp::Subtract:
            return describeOperand(p, n.a) + "-" + describeOperand(p, n.b);
        case ExprOp::Multiply:
            return describeOperand(p, n.a) + "*" + describeOperand(p, n.b);
        case ExprOp::Divide:
            return describeOperand(p, n.a) + "/" + describeOperand(p, n.b);
        case ExprOp::ReadM:
            return "M(" + describeExpr(p, n.a) + ")";
        case ExprOp::ReadG:
            return "G(" + describeExpr(p, n.a) + ")";
        case ExprOp::ReadT:
            return "T";
        case ExprOp::ReadE:
            return "E";
        case ExprOp::ReadQ:
            return "Q";
        case ExprOp::ReadS:
            return n.index ? "S" + std::to_string(n.index) : "S";
        case ExprOp::ReadSPC:
            return "SPC";
        case ExprOp::ReadTime:
            return "TIME";
        case ExprOp::ReadMTD:
            return "MTD(" + describeExpr(p, n.a) + "," + describeExpr(p, n.b) + "," +
                   describeExpr(p, n.c) + "," + describeExpr(p, n.d) + ")";
        case ExprOp::ReadAXD: {
            std::string axis(1, static_cast<char>(n.index / 10));
            if (n.index % 10) axis += static_cast<char>('0' + n.index % 10);
            return "AXD(" + axis + ":P-7-" + std::to_string(static_cast<int>(n.value)) + ")";
        }
    }
    return "?";
}

inline std::string describeValue(const Program& p, const Word& w) {
    return w.expr >= 0 ? describeExpr(p, w.expr) : formatNumber(w.number);
}

inline std::string describeWord(const Program& p, const Word& w) {
    std::string name;
    switch (w.kind) {
        case WordKind::G:
            name = "G";
            break;
        case WordKind::M:
            name = w.flags & kWordSwift ? "MQ" : "M";
            break;
        case WordKind::Q:
            name = w.flags & kWordSwift ? "QQ" : "Q";
            break;
        case WordKind::S:
            name = "S";
            break;
        case WordKind::T:
            name = "T";
            break;
        case WordKind::E:
            name = "E";
            break;
        case WordKind::F:
            name = "F";
            break;
        case WordKind::D:
            name = "D";
            break;
        case WordKind::Axis:
        case WordKind::CircleCenter:
            name = std::string(1, w.letter);
            break;
        case WordKind::EffectiveRadius:
            name = "RI";
            break;
        case WordKind::Assign:
        case WordKind::AssignMTD:
            return describeExpr(p, w.target) + "=" + describeValue(p, w);
        case WordKind::Jump: {
            std::string text(jumpName(w.jump));
            if (!w.text.empty()) text += " ." + std::string(p.text(w.text));
            if (w.jump == JumpKind::JSR || w.jump == JumpKind::JMP || w.jump == JumpKind::JEV)
                text += " " + describeValue(p, w);
            if (w.eventNumber >= 0)
                text += " " + std::to_string(w.eventProcess) + ":" + std::to_string(w.eventNumber);
            return text;
        }
        case WordKind::Command:
            return std::string(w.flags & kWordNeedsCompiler ? "COMPILER[" : "CMD[") +
                   std::string(p.text(w.text)) + "]";
    }
    if (w.axisIndex) name += std::to_string(w.axisIndex);
    bool separate = w.axisIndex || w.expr >= 0 || w.kind == WordKind::EffectiveRadius;
    return name + (separate ? "=" : "") + describeValue(p, w);
}

/// The words of block `index`, space-separated.
inline std::string describeBlock(const Program& p, std::size_t index) {
    const Block b = p.blocks[index];
    std::string text;
    for (std::uint32_t i = b.firstWord; i < b.firstWord + b.wordCount; ++i) {
        if (!text.empty()) text += ' ';
        text += describeWord(p, p.words[i]);
    }
    return text;
}

/// Diagnostic codes in order.
inline std::vector<std::string> codes(const Program& p) {
    std::vector<std::string> result;
    for (const auto& d : p.diagnostics.items())
        result.push_back(d.code);
    return result;
}

/// The first diagnostic with `code`, or nullptr.
inline const Diagnostic* find(const Program& p, const std::string& code) {
    for (const auto& d : p.diagnostics.items())
        if (d.code == code) return &d;
    return nullptr;
}

}  // namespace mtc::core::testing
