#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace mtc::cli {

/// A small streaming JSON writer. Output goes through an internal buffer to a
/// C stream, so a document of a million motions is written piece by piece and
/// never held in memory as a whole. Commas are inserted automatically; strings
/// are escaped (control characters as \u00XX, invalid UTF-8 as U+FFFD); numbers
/// that are not finite are written as null, never as NaN or inf.
class JsonWriter {
  public:
    /// Writes to `stream` (not owned). `indent` > 0 pretty-prints with that many
    /// blanks per level; 0 writes compact JSON.
    explicit JsonWriter(std::FILE* stream, int indent = 0);
    /// Flushes what is still buffered.
    ~JsonWriter();
    JsonWriter(const JsonWriter&) = delete;
    JsonWriter& operator=(const JsonWriter&) = delete;

    /// Opens an object or array (as a value: after key() or inside an array).
    void beginObject();
    void endObject();
    void beginArray();
    void endArray();
    /// Writes an object key; the next call must write its value.
    void key(std::string_view name);
    void value(std::string_view text);
    void value(const char* text) { value(std::string_view(text)); }
    void value(const std::string& text) { value(std::string_view(text)); }
    void value(double number);
    void value(int number) { value(static_cast<long long>(number)); }
    void value(long number) { value(static_cast<long long>(number)); }
    void value(unsigned number) { value(static_cast<long long>(number)); }
    void value(unsigned long number) { value(static_cast<long long>(number)); }
    void value(long long number);
    void value(bool flag);
    void null();
    /// One member of the open object: key(name), then value(v).
    template <typename T>
    void field(std::string_view name, const T& v) {
        key(name);
        value(v);
    }
    /// Ends the document with a newline and flushes the stream.
    void finish();

    /// Appends the JSON string literal of `text` (with quotes) to `out`.
    static void appendEscaped(std::string& out, std::string_view text);
    /// Appends the shortest text that reads back as `number`; "null" when it is
    /// not finite. Negative zero is written as 0.
    static void appendNumber(std::string& out, double number);

  private:
    void beforeValue();
    void newline();
    void flushIfFull();
    void flush();

    std::FILE* stream_;
    int indent_;
    std::string buffer_;
    std::vector<bool> firstInScope_;  ///< one entry per open object/array
    bool afterKey_ = false;
};

}  // namespace mtc::cli
