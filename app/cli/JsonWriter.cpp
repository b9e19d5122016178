#include "cli/JsonWriter.h"

#include <charconv>
#include <cmath>

namespace mtc::cli {

namespace {

constexpr std::size_t kFlushThreshold = 1 << 16;

/// Length of the valid UTF-8 sequence starting at text[i], or 0 when invalid.
std::size_t utf8SequenceLength(std::string_view text, std::size_t i) {
    const auto lead = static_cast<unsigned char>(text[i]);
    std::size_t length = 0;
    unsigned minimum = 0;
    unsigned codePoint = 0;
    if (lead >= 0xC2 && lead <= 0xDF) {
        length = 2, minimum = 0x80, codePoint = lead & 0x1Fu;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
        length = 3, minimum = 0x800, codePoint = lead & 0x0Fu;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
        length = 4, minimum = 0x10000, codePoint = lead & 0x07u;
    } else {
        return 0;
    }
    if (i + length > text.size()) return 0;
    for (std::size_t k = 1; k < length; ++k) {
        const auto next = static_cast<unsigned char>(text[i + k]);
        if ((next & 0xC0u) != 0x80u) return 0;
        codePoint = (codePoint << 6) | (next & 0x3Fu);
    }
    if (codePoint < minimum || codePoint > 0x10FFFF) return 0;
    if (codePoint >= 0xD800 && codePoint <= 0xDFFF) return 0;
    return length;
}

void appendControl(std::string& out, unsigned char c) {
    switch (c) {
        case '\n':
            out += "\\n";
            return;
        case '\r':
            out += "\\r";
            return;
        case '\t':
            out += "\\t";
            return;
        case '\b':
            out += "\\b";
            return;
        case '\f':
            out += "\\f";
            return;
        default:
            break;
    }
    static const char* const kHex = "0123456789abcdef";
    out += "\\u00";
    out += kHex[c >> 4];
    out += kHex[c & 0x0F];
}

}  // namespace

JsonWriter::JsonWriter(std::FILE* stream, int indent) : stream_(stream), indent_(indent) {
    buffer_.reserve(kFlushThreshold * 2);
}

JsonWriter::~JsonWriter() {
    flush();
}

void JsonWriter::appendEscaped(std::string& out, std::string_view text) {
    out += '"';
    std::size_t i = 0;
    while (i < text.size()) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += static_cast<char>(c);
            ++i;
        } else if (c < 0x20 || c == 0x7F) {
            appendControl(out, c);
            ++i;
        } else if (c < 0x80) {
            out += static_cast<char>(c);
            ++i;
        } else if (std::size_t length = utf8SequenceLength(text, i); length > 0) {
            out.append(text.substr(i, length));
            i += length;
        } else {
            out += "\\ufffd";
            ++i;
        }
    }
    out += '"';
}

void JsonWriter::appendNumber(std::string& out, double number) {
    if (!std::isfinite(number)) {
        out += "null";
        return;
    }
    if (number == 0.0) number = 0.0;  // drops the sign of -0
    char text[32];
    auto result = std::to_chars(text, text + sizeof text, number);
    out.append(text, result.ptr);
}

void JsonWriter::newline() {
    if (indent_ <= 0) return;
    buffer_ += '\n';
    buffer_.append(firstInScope_.size() * static_cast<std::size_t>(indent_), ' ');
}

void JsonWriter::beforeValue() {
    if (afterKey_) {
        afterKey_ = false;
        return;
    }
    if (!firstInScope_.empty()) {
        if (!firstInScope_.back()) buffer_ += ',';
        firstInScope_.back() = false;
        newline();
    }
}

void JsonWriter::beginObject() {
    beforeValue();
    buffer_ += '{';
    firstInScope_.push_back(true);
}

void JsonWriter::endObject() {
    const bool empty = !firstInScope_.empty() && firstInScope_.back();
    if (!firstInScope_.empty()) firstInScope_.pop_back();
    if (!empty) newline();
    buffer_ += '}';
    flushIfFull();
}

void JsonWriter::beginArray() {
    beforeValue();
    buffer_ += '[';
    firstInScope_.push_back(true);
}

void JsonWriter::endArray() {
    const bool empty = !firstInScope_.empty() && firstInScope_.back();
    if (!firstInScope_.empty()) firstInScope_.pop_back();
    if (!empty) newline();
    buffer_ += ']';
    flushIfFull();
}

void JsonWriter::key(std::string_view name) {
    beforeValue();
    appendEscaped(buffer_, name);
    buffer_ += indent_ > 0 ? ": " : ":";
    afterKey_ = true;
}

void JsonWriter::value(std::string_view text) {
    beforeValue();
    appendEscaped(buffer_, text);
    flushIfFull();
}

void JsonWriter::value(double number) {
    beforeValue();
    appendNumber(buffer_, number);
}

void JsonWriter::value(long long number) {
    beforeValue();
    char text[24];
    auto result = std::to_chars(text, text + sizeof text, number);
    buffer_.append(text, result.ptr);
}

void JsonWriter::value(bool flag) {
    beforeValue();
    buffer_ += flag ? "true" : "false";
}

void JsonWriter::null() {
    beforeValue();
    buffer_ += "null";
}

void JsonWriter::finish() {
    buffer_ += '\n';
    flush();
    std::fflush(stream_);
}

void JsonWriter::flushIfFull() {
    if (buffer_.size() >= kFlushThreshold) flush();
}

void JsonWriter::flush() {
    if (buffer_.empty() || stream_ == nullptr) return;
    std::fwrite(buffer_.data(), 1, buffer_.size(), stream_);
    buffer_.clear();
}

}  // namespace mtc::cli
