#include "cnc_core/tooldata/DataFileText.h"

#include "cnc_core/machine/ConfigWords.h"
#include "cnc_core/text/Numbers.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace mtc::core {

namespace {

/// [+-]digits[.digits][e[+-]digits] with at least one digit in the mantissa.
bool decimalSyntax(const std::string& s) {
    std::size_t i = 0, n = s.size();
    if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
    std::size_t digits = 0;
    while (i < n && s[i] >= '0' && s[i] <= '9')
        ++i, ++digits;
    if (i < n && s[i] == '.') {
        ++i;
        while (i < n && s[i] >= '0' && s[i] <= '9')
            ++i, ++digits;
    }
    if (digits == 0) return false;
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        ++i;
        if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
        std::size_t exponent = 0;
        while (i < n && s[i] >= '0' && s[i] <= '9')
            ++i, ++exponent;
        if (exponent == 0) return false;
    }
    return i == n;
}

}  // namespace

void DataFileText::refuse(int line, const std::string& key, const std::string& value,
                          const std::string& problem) {
    failed_ = true;
    diagnostics_.error(
        code_, {0, "", line, 0},
        file_ + ":" + std::to_string(line) + ": key '" + key + "' = '" + value + "': " + problem);
}

void DataFileText::refuseLine(int line, const std::string& problem) {
    failed_ = true;
    diagnostics_.error(code_, {0, "", line, 0},
                       file_ + ":" + std::to_string(line) + ": " + problem);
}

bool DataFileText::number(int line, const std::string& key, const std::string& value, double low,
                          double high, const char* unit, double& out) {
    auto range = [&] {  // only built for a refusal
        return "allowed " + formatDataNumber(low) + " .. " + formatDataNumber(high) +
               (unit[0] ? std::string(" ") + unit : "");
    };
    if (!decimalSyntax(value)) {
        refuse(line, key, value, "not a decimal number (" + range() + ")");
        return false;
    }
    const double v = leadingNumber(value);
    if (!std::isfinite(v) || v < low || v > high) {
        refuse(line, key, value, "out of range (" + range() + ")");
        return false;
    }
    out = v == 0.0 ? 0.0 : v;  // no -0 in the data
    return true;
}

bool DataFileText::integer(int line, const std::string& key, const std::string& value,
                           long long low, long long high, long long& out) {
    auto range = [&] { return "allowed " + std::to_string(low) + " .. " + std::to_string(high); };
    bool digits = !value.empty();
    for (std::size_t i = 0; i < value.size(); ++i)
        digits = digits && ((value[i] >= '0' && value[i] <= '9') ||
                            (i == 0 && value[i] == '-' && value.size() > 1));
    if (!digits || value.size() > 18) {
        refuse(line, key, value, "not a whole number (" + range() + ")");
        return false;
    }
    const long long v = std::strtoll(value.c_str(), nullptr, 10);
    if (v < low || v > high) {
        refuse(line, key, value, "out of range (" + range() + ")");
        return false;
    }
    out = v;
    return true;
}

// The configuration's word rules, so the data files and the machine
// configuration split and trim text the same way.
std::string_view trimmedText(std::string_view s) {
    return trimConfigText(s);
}

std::vector<std::string_view> wordsOf(std::string_view text) {
    return splitConfigWords(text);
}

std::string formatDataNumber(double value) {
    if (value == 0.0) return "0";
    std::string text;
    for (int digits = 6; digits <= 17; ++digits) {
        text = formatGeneral(value, digits);
        if (leadingNumber(text) == value) break;
    }
    return text;
}

}  // namespace mtc::core

namespace mtc::core {

namespace {

/// "key = value" split at the first '='; false without one.
bool keyValue(std::string_view line, std::string& key, std::string& value) {
    const std::size_t eq = line.find('=');
    if (eq == std::string_view::npos) return false;
    key = std::string(trimmedText(line.substr(0, eq)));
    value = std::string(trimmedText(line.substr(eq + 1)));
    return true;
}

}  // namespace

std::string dataFrameHeader(std::string_view formatName) {
    return "format = " + std::string(formatName) + " 1\n";
}

bool readDataFrame(std::string_view text, std::string_view formatName, DataFileText& out,
                   const std::function<void(int, int, std::string_view)>& record,
                   const std::function<void(int)>& section) {
    bool header = false, ended = false;
    int process = -1, line = 0;
    long long records = 0;
    std::vector<bool> seen(7, false);
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t nl = text.find('\n', pos);
        if (nl == std::string_view::npos) nl = text.size();
        const std::string_view raw = text.substr(pos, nl - pos);
        pos = nl + 1;
        ++line;
        const std::string_view body = trimmedText(raw.substr(0, raw.find('#')));
        if (body.empty()) continue;
        std::string key, value;
        if (ended) {
            out.refuseLine(line, "nothing may follow the 'end' line");
            return false;
        }
        if (!header) {
            if (!keyValue(body, key, value) || key != "format" ||
                value != std::string(formatName) + " 1") {
                out.refuseLine(
                    line, "the file must start with 'format = " + std::string(formatName) + " 1'");
                return false;
            }
            header = true;
            continue;
        }
        if (body.front() == '[') {
            const std::vector<std::string_view> words =
                wordsOf(body.substr(1, body.back() == ']' ? body.size() - 2 : body.size() - 1));
            long long n = 0;
            if (body.back() != ']' || words.size() != 2 || words[0] != "process") {
                out.refuseLine(line, "expected a section '[process N]'");
                return false;
            }
            if (!out.integer(line, "process", std::string(words[1]), 0, 6, n)) return false;
            if (seen[static_cast<std::size_t>(n)]) {
                out.refuse(line, "process", std::string(words[1]), "section given twice");
                return false;
            }
            seen[static_cast<std::size_t>(n)] = true;
            process = static_cast<int>(n);
            if (section) section(process);
            continue;
        }
        if (keyValue(body, key, value) && key == "end") {
            long long count = 0;
            if (!out.integer(line, "end", value, 0, 100000000, count)) return false;
            if (count != records) {
                out.refuse(line, "end", value,
                           "the file holds " + std::to_string(records) + " records");
                return false;
            }
            ended = true;
            continue;
        }
        if (process < 0) {
            out.refuseLine(line, "a record before any '[process N]' section");
            return false;
        }
        ++records;
        record(line, process, body);
    }
    if (!header)
        out.refuseLine(line, "empty file: no 'format' line");
    else if (!ended)
        out.refuseLine(line, "no 'end = N' line: the file is cut off or incomplete");
    return !out.failed();
}

}  // namespace mtc::core
