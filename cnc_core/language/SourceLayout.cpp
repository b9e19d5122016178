#include "cnc_core/language/SourceLayout.h"

#include <charconv>
#include <string>

namespace mtc::core {

namespace {

/// One line of the source: [begin, end) without '\r\n'; next = start of the next line.
struct Line {
    std::uint32_t begin = 0;
    std::uint32_t end = 0;
    std::uint32_t next = 0;
    std::uint32_t number = 0;
};

class LineReader {
  public:
    LineReader(ParseContext& context, std::uint32_t begin)
        : context_(context), text_(context.source()), pos_(begin) {}
    /// Number of the last line read (0 before the first).
    std::uint32_t lastNumber() const { return number_; }
    bool next(Line& line) {
        if (pos_ >= text_.size()) return false;
        if (pos_ >= ready_) ready_ = context_.readyLinesFrom(pos_);
        std::size_t nl = text_.find('\n', pos_);
        std::uint32_t end = nl == std::string_view::npos ? static_cast<std::uint32_t>(text_.size())
                                                         : static_cast<std::uint32_t>(nl);
        line.begin = pos_;
        line.next = nl == std::string_view::npos ? end : end + 1;
        if (end > pos_ && text_[end - 1] == '\r') --end;
        line.end = end;
        line.number = ++number_;
        pos_ = line.next;
        return true;
    }

  private:
    ParseContext& context_;
    std::string_view text_;
    std::uint32_t pos_;
    std::uint32_t number_ = 0;
    std::uint32_t ready_ = 0;  ///< line starts below it are ready
};

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t'))
        s.remove_suffix(1);
    return s;
}

bool startsWith(std::string_view s, std::string_view prefix) {
    return s.substr(0, prefix.size()) == prefix;
}

bool isHeaderOpen(std::string_view line) {
    return startsWith(line, "%NPG") || startsWith(line, "%MAC");
}

/// A line that can only be an NC block ("N0000 ..."): ends a header that
/// lacks its closing line.
bool looksLikeBlock(std::string_view line) {
    line = trimmed(line);
    return line.size() >= 2 && line[0] == 'N' && line[1] >= '0' && line[1] <= '9';
}

/// "%NPG:u:xx:y:zzz" -> zzz, or 0.
int headerProgramNumber(std::string_view open) {
    std::size_t last = open.rfind(':');
    if (last == std::string_view::npos || open.find(':') == last) return 0;
    std::string_view digits = trimmed(open.substr(last + 1));
    int value = 0;
    auto [ptr, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error != std::errc() || ptr != digits.data() + digits.size() || value < 0) return 0;
    return value;
}

/// "%V% @141 INT[1,2] prompt text" -> CycleParameter; false when malformed.
bool parseCycleParameter(std::string_view text, CycleParameter& parameter) {
    text = trimmed(text.substr(3));
    if (text.empty() || text[0] != '@') return false;
    std::size_t i = 1;
    int variable = 0;
    auto [ptr, error] = std::from_chars(text.data() + 1, text.data() + text.size(), variable);
    if (error != std::errc()) return false;
    i = static_cast<std::size_t>(ptr - text.data());
    parameter.variable = variable;
    text = trimmed(text.substr(i));
    std::size_t typeEnd = 0;
    while (typeEnd < text.size() && text[typeEnd] >= 'A' && text[typeEnd] <= 'Z')
        ++typeEnd;
    if (typeEnd == 0) return false;
    parameter.type = std::string(text.substr(0, typeEnd));
    text = text.substr(typeEnd);
    if (!text.empty() && text[0] == '[') {
        std::size_t close = text.find(']');
        std::size_t comma = text.find(',');
        if (close == std::string_view::npos || comma == std::string_view::npos || comma > close)
            return false;
        std::string low(trimmed(text.substr(1, comma - 1)));
        std::string high(trimmed(text.substr(comma + 1, close - comma - 1)));
        auto r1 = std::from_chars(low.data(), low.data() + low.size(), parameter.minimum);
        auto r2 = std::from_chars(high.data(), high.data() + high.size(), parameter.maximum);
        if (r1.ec != std::errc() || r2.ec != std::errc()) return false;
        parameter.hasRange = true;
        text = text.substr(close + 1);
    }
    parameter.text = std::string(trimmed(text));
    return true;
}

class LayoutReader {
  public:
    explicit LayoutReader(ParseContext& context)
        : context_(context), program_(context.program()), text_(context.source()) {}

    SourceLayout read();

  private:
    bool readHeader(LineReader& lines, const Line& open, Line& after, bool& haveAfter);
    void readCycleDeclarations(LineReader& lines, const Line& open, Line& after, bool& haveAfter);
    std::string_view view(const Line& line) const {
        return text_.substr(line.begin, line.end - line.begin);
    }
    void report(Severity severity, const char* code, const Line& line, std::string message) {
        context_.report(severity, code, line.number, 1, "", std::move(message));
    }

    ParseContext& context_;
    Program& program_;
    std::string_view text_;
};

SourceLayout LayoutReader::read() {
    SourceLayout layout;
    context_.readyLinesFrom(0);
    std::uint32_t start = startsWith(text_, "\xEF\xBB\xBF") ? 3 : 0;  // UTF-8 byte order mark
    layout.blocksBegin = start;
    LineReader lines(context_, start);
    Line first, second;
    if (!lines.next(first)) return layout;
    Line open;
    if (isHeaderOpen(view(first))) {
        report(Severity::Warning, "DAT_MISSING_IDENTIFICATION", first,
               "the file has no identification line before its header");
        open = first;
    } else if (lines.next(second) && isHeaderOpen(view(second))) {
        program_.identification = std::string(view(first));
        open = second;
    } else {
        return layout;  // loose file of blocks
    }
    layout.dat = true;
    program_.isCycle = startsWith(view(open), "%MAC");
    if (program_.number == 0) program_.number = headerProgramNumber(view(open));
    Line after;
    bool haveAfter = false;
    if (readHeader(lines, open, after, haveAfter) && haveAfter &&
        startsWith(trimmed(view(after)), "%CHBEGIN%"))
        readCycleDeclarations(lines, after, after, haveAfter);
    layout.blocksBegin = haveAfter ? after.begin : static_cast<std::uint32_t>(text_.size());
    // No block line: the blocks would begin after the file's last line (a
    // problem reported at the end of the file then names that line).
    layout.firstLine = haveAfter ? after.number : lines.lastNumber() + 1;
    return layout;
}

bool LayoutReader::readHeader(LineReader& lines, const Line& open, Line& after, bool& haveAfter) {
    std::string_view kind = view(open).substr(0, 4);
    Line line;
    std::uint32_t headerEnd = open.end;
    while (lines.next(line)) {
        std::string_view content = trimmed(view(line));
        if (content == "%NPG" || content == "%MAC") {
            if (content != kind)
                report(Severity::Warning, "DAT_HEADER_MISMATCH", line,
                       "header opened with " + std::string(kind) + " but closed with " +
                           std::string(content));
            program_.header = std::string(text_.substr(open.begin, line.end - open.begin));
            haveAfter = lines.next(after);
            return true;
        }
        if (looksLikeBlock(content)) {
            after = line;
            haveAfter = true;
            break;
        }
        if (!content.empty() && content[0] == '*' && program_.title.empty())
            program_.title = std::string(trimmed(content.substr(1)));
        headerEnd = line.end;
    }
    report(Severity::Error, "DAT_UNTERMINATED_HEADER", open,
           "the header is not closed with a " + std::string(kind) + " line");
    program_.header = std::string(text_.substr(open.begin, headerEnd - open.begin));
    return false;
}

void LayoutReader::readCycleDeclarations(LineReader& lines, const Line& open, Line& after,
                                         bool& haveAfter) {
    Line line;
    haveAfter = false;
    while (lines.next(line)) {
        std::string_view content = trimmed(view(line));
        if (startsWith(content, "%CHEND%")) {
            haveAfter = lines.next(after);
            return;
        }
        if (looksLikeBlock(content)) {
            after = line;
            haveAfter = true;
            break;
        }
        if (startsWith(content, "%V%")) {
            CycleParameter parameter;
            parameter.line = line.number;
            if (parseCycleParameter(content, parameter))
                program_.cycleParameters.push_back(std::move(parameter));
            else
                report(Severity::Warning, "DAT_BAD_CYCLE_PARAMETER", line,
                       "cycle parameter: %V% @n TYPE[min,max] text");
        } else if (startsWith(content, "%N%")) {
            program_.cycleCall = std::string(trimmed(content.substr(3)));
        } else if (!content.empty()) {
            report(Severity::Warning, "DAT_BAD_CYCLE_PARAMETER", line,
                   "unknown line in the cycle declarations (%V% or %N% expected)");
        }
    }
    report(Severity::Error, "DAT_UNTERMINATED_CYCLE_DECLARATIONS", open,
           "%CHBEGIN% is not closed with %CHEND%");
}

}  // namespace

SourceLayout readSourceLayout(ParseContext& context) {
    return LayoutReader(context).read();
}

}  // namespace mtc::core
