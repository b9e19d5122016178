#include "cnc_core/compiler/lookahead/CompileTimeValue.h"

#include <cctype>
#include <cmath>

#include "cnc_core/text/Numbers.h"

namespace mtc::core::lookahead {
namespace {

class ValueParser {
  public:
    ValueParser(std::string_view text, int process, const NcVariableReader& reader)
        : text_(text), process_(process), reader_(reader) {}

    CompileTimeValue run() {
        CompileTimeValue result;
        skipBlanks();
        const double v = expression(0);
        skipBlanks();
        if (problem_.empty() && pos_ < text_.size())
            problem_ = "unexpected '" + std::string(1, text_[pos_]) + "'";
        if (problem_.empty() && !std::isfinite(v)) problem_ = "value is not finite";
        result.ok = problem_.empty();
        result.value = result.ok ? v : 0.0;
        result.problem = problem_;
        result.unreadVariables = unread_;
        return result;
    }

  private:
    static constexpr int kMaxDepth = 32;

    void skipBlanks() {
        while (pos_ < text_.size() && text_[pos_] == ' ')
            ++pos_;
    }
    bool accept(char c) {
        skipBlanks();
        if (pos_ < text_.size() && text_[pos_] == c) {
            ++pos_;
            return true;
        }
        return false;
    }
    double fail(std::string why) {
        if (problem_.empty()) problem_ = std::move(why);
        pos_ = text_.size();
        return 0.0;
    }

    double expression(int depth) {
        double v = term(depth);
        for (;;) {
            if (accept('+'))
                v += term(depth);
            else if (accept('-'))
                v -= term(depth);
            else
                return v;
        }
    }
    double term(int depth) {
        double v = factor(depth);
        for (;;) {
            if (accept('*')) {
                v *= factor(depth);
            } else if (accept('/')) {
                const double d = factor(depth);
                if (d == 0.0) return fail("division by zero");
                v /= d;
            } else {
                return v;
            }
        }
    }
    double factor(int depth) {
        if (depth > kMaxDepth) return fail("expression nested too deeply");
        skipBlanks();
        if (accept('-')) return -factor(depth + 1);
        if (accept('+')) return factor(depth + 1);
        if (accept('(')) {
            const double v = expression(depth + 1);
            if (!accept(')')) return fail("missing ')'");
            return v;
        }
        if (pos_ < text_.size() && (std::isdigit(static_cast<unsigned char>(text_[pos_])) ||
                                    text_[pos_] == '.' || text_[pos_] == ','))
            return number();
        if (text_.substr(pos_, 8) == "ACD_COMP") return controllerValue(8);
        if (text_.substr(pos_, 3) == "ACD") return controllerValue(3);
        return fail(pos_ < text_.size() ? "unexpected '" + std::string(1, text_[pos_]) + "'"
                                        : "value missing");
    }
    double number() {
        std::string digits;
        while (pos_ < text_.size() && (std::isdigit(static_cast<unsigned char>(text_[pos_])) ||
                                       text_[pos_] == '.' || text_[pos_] == ',')) {
            digits += text_[pos_] == ',' ? '.' : text_[pos_];
            ++pos_;
        }
        if (digits.size() > 20 || digits.find('.') != digits.rfind('.') || digits == ".")
            return fail("bad number '" + digits + "'");
        return leadingNumber(digits);
    }
    /// ACD_COMP[@n] or ACD_COMP[@p:n].
    double controllerValue(size_t keywordLength) {
        pos_ += keywordLength;
        if (!accept('[') || !accept('@')) return fail("ACD_COMP needs [@variable]");
        long first = integer(), second = -1;
        if (accept(':')) second = integer();
        if (!accept(']') || first < 0) return fail("ACD_COMP needs [@variable]");
        const int process = second >= 0 ? static_cast<int>(first) : process_;
        const int number = static_cast<int>(second >= 0 ? second : first);
        if (process > 127 || number > 65535) return fail("ACD_COMP variable out of range");
        const std::optional<double> v = reader_ ? reader_(process, number) : std::nullopt;
        if (!v) unread_.push_back("@" + std::to_string(process) + ":" + std::to_string(number));
        return v.value_or(0.0);
    }
    long integer() {
        skipBlanks();
        long v = 0;
        size_t digits = 0;
        while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_])) &&
               digits < 9) {
            v = v * 10 + (text_[pos_++] - '0');
            ++digits;
        }
        return digits == 0 ? -1 : v;
    }

    std::string_view text_;
    int process_;
    const NcVariableReader& reader_;
    size_t pos_ = 0;
    std::string problem_;
    std::vector<std::string> unread_;
};

}  // namespace

CompileTimeValue evaluateCompileTimeValue(std::string_view text, int process,
                                          const NcVariableReader& reader) {
    return ValueParser(text, process, reader).run();
}

}  // namespace mtc::core::lookahead
