// readGne(): the GNE keywords of a program text into a GneDocument.

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>
#include "cnc_core/text/Numbers.h"

#include "cnc_core/contour/GneSchema.h"
#include "cnc_core/contour/GneText.h"
#include "cnc_core/language/CheckedNumber.h"

namespace mtc::core::gne {
namespace {

bool isElementKeyword(const std::string& k) {
    return k == "START" || k == "LINE" || k == "CW" || k == "CCW" || k == "RD" || k == "CF" ||
           k == "RELIEF";
}

/// Reads a whole token as a finite number.
bool toNumber(const std::string& token, double& value) {
    if (token.empty() || token.size() > 40) return false;
    for (char c : token)
        if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+'))
            return false;
    return readNumberPrefix(token, value) == token.size() && std::isfinite(value);
}

std::string trim(const std::string& s) {
    std::size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
    return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

class Reader {
  public:
    explicit Reader(std::uint32_t firstLine) : lineNumber_(firstLine) {}

    GneDocument run(std::string_view text) {
        std::size_t pos = 0;
        while (pos <= text.size()) {
            std::size_t eol = text.find('\n', pos);
            if (eol == std::string_view::npos) eol = text.size();
            readLine(std::string(text.substr(pos, eol - pos)));
            ++lineNumber_;
            pos = eol + 1;
        }
        if (open_) {
            error(doc_.items.back().contour.line, "GNE_CONT_NOT_CLOSED", "CONT without END_CONT");
            endContour(lineNumber_ - 1);
        }
        return std::move(doc_);
    }

  private:
    void error(std::uint32_t line, const char* code, const std::string& message) {
        doc_.diagnostics.push_back({line, code, message});
    }
    void error(const char* code, const std::string& message) { error(lineNumber_, code, message); }

    /// Removes the ';' comment (outside quotes) and the block prefix
    /// ('/', N number with enhanced number, ':'); upper-cases outside quotes.
    static std::string body(std::string line) {
        bool quoted = false;
        for (std::size_t i = 0; i < line.size(); ++i) {
            char& c = line[i];
            if (c == '"')
                quoted = !quoted;
            else if (c == ';' && !quoted) {
                line.resize(i);
                break;
            } else if (!quoted)
                c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        }
        std::string s = trim(line);
        if (!s.empty() && s[0] == '/') s = trim(s.substr(1));
        if (s.size() > 1 && s[0] == 'N' && std::isdigit(static_cast<unsigned char>(s[1]))) {
            std::size_t i = 1;
            while (i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == ':'))
                ++i;
            s = trim(s.substr(i));
        }
        if (!s.empty() && s[0] == ':') s = trim(s.substr(1));
        return s;
    }

    void readLine(std::string raw) {
        if (!raw.empty() && raw.back() == '\r') raw.pop_back();
        const std::string s = body(raw);
        std::size_t i = 0;
        while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '_'))
            ++i;
        const std::string keyword = s.substr(0, i);
        const std::string rest = trim(s.substr(i));
        if (keyword == "CONT") return openContour(rest);
        if (keyword == "END_CONT") return closeContour(rest);
        if (isElementKeyword(keyword) && (open_ || (keyword != "RD" && keyword != "CF"))) {
            if (!open_)
                return error("GNE_ELEMENT_OUTSIDE_CONT", keyword + " outside CONT ... END_CONT");
            return readElement(keyword, rest);
        }
        const bool call = keyword.rfind("WINDOW_", 0) == 0 || keyword.rfind("FORM_", 0) == 0 ||
                          keyword.rfind("CYCLE_", 0) == 0;
        if (open_ && call) {  // END_CONT forgotten: the contour ends before this line
            error(doc_.items.back().contour.line, "GNE_CONT_NOT_CLOSED",
                  "CONT without END_CONT (it ends before " + keyword + ")");
            endContour(lineNumber_ - 1);
        }
        if (open_) {
            if (!s.empty())
                error("GNE_NOT_AN_ELEMENT",
                      "only contour elements (START, LINE, CW, CCW, RD, CF, RELIEF) may stand "
                      "between CONT and END_CONT");
            return;
        }
        if (call) readCall(keyword, rest);
    }

    void openContour(const std::string& rest) {
        if (open_) {
            error("GNE_CONT_NESTED", "CONT inside a contour: END_CONT is missing");
            closeContour("");
        }
        GneItem item;
        item.isContour = true;
        item.contour.line = lineNumber_;
        item.contour.plane = plane_.value_or(GnePlane::Turning);
        if (!plane_)
            error("GNE_NO_WINDOW",
                  "CONT needs a WINDOW_01 (turning) or WINDOW_02 (milling) before it");
        std::vector<std::string> args;
        if (!splitArgs(rest, args) || args.empty() || args.size() > 2)
            error("GNE_CONT_SYNTAX", "write CONT (number) or CONT (number, FINAL|RAW)");
        double n = 0;
        if (!args.empty() && (!toNumber(args[0], n) || n < 1 || n > 9999 || std::floor(n) != n))
            error("GNE_CONT_NUMBER", "the contour number must be a whole number 1..9999");
        item.contour.number = exactInteger(n).value_or(0);
        if (args.size() == 2) {
            if (args[1] == "RAW")
                item.contour.raw = true;
            else if (args[1] != "FINAL")
                error("GNE_CONT_KIND", "the contour kind is FINAL or RAW, not '" + args[1] + "'");
        }
        doc_.items.push_back(std::move(item));
        open_ = true;
    }

    void closeContour(const std::string& rest) {
        if (!open_) return error("GNE_END_CONT_ALONE", "END_CONT without CONT");
        if (!rest.empty()) error("GNE_END_CONT_SYNTAX", "END_CONT takes no parameters");
        endContour(lineNumber_);
    }

    /// Ends the open contour at `line`.
    void endContour(std::uint32_t line) {
        Contour& c = doc_.items.back().contour;
        c.endLine = line;
        open_ = false;
        if (c.elements.empty() || c.elements.front().kind != ElementKind::Start)
            error(c.line, "GNE_NO_START", "a contour begins with START");
    }

    /// Splits "(a, b, "t")" into trimmed arguments; false on bad brackets.
    static bool splitArgs(const std::string& rest, std::vector<std::string>& args) {
        if (rest.size() < 2 || rest.front() != '(' || rest.back() != ')') return false;
        std::string current;
        bool quoted = false;
        for (std::size_t i = 1; i + 1 < rest.size(); ++i) {
            char c = rest[i];
            if (c == '"') quoted = !quoted;
            if (c == ',' && !quoted) {
                args.push_back(trim(current));
                current.clear();
            } else {
                current += c;
            }
        }
        if (quoted) return false;
        args.push_back(trim(current));
        if (args.size() == 1 && args[0].empty()) args.clear();
        return true;
    }

    void readCall(const std::string& keyword, const std::string& rest) {
        const CallSpec* spec = findCallSpec(keyword);
        if (!spec)
            return error("GNE_UNKNOWN_KEYWORD",
                         keyword + " is not a GNE instruction of this control");
        std::vector<std::string> args;
        if (!splitArgs(rest, args))
            return error("GNE_SYNTAX", keyword + ": parameters are written in brackets: " +
                                           keyword + " (..., ...)");
        GneCall call;
        call.keyword = keyword;
        call.line = lineNumber_;
        if (spec->hasText) {
            if (args.empty() || args.back().size() < 2 || args.back().front() != '"' ||
                args.back().back() != '"')
                return error("GNE_TEXT_MISSING", keyword + " ends with the text in quotes");
            call.text = args.back().substr(1, args.back().size() - 2);
            args.pop_back();
            if (call.text.empty())
                return error("GNE_TEXT_MISSING", keyword + ": the text is empty");
        }
        if (args.size() > spec->params.size())
            return error("GNE_TOO_MANY", keyword + " takes " + std::to_string(spec->params.size()) +
                                             " parameters, not " + std::to_string(args.size()));
        bool good = true;
        for (std::size_t i = 0; i < spec->params.size(); ++i) {
            std::optional<double> value;
            if (i < args.size() && !args[i].empty()) {
                double v = 0;
                if (!toNumber(args[i], v)) {
                    error("GNE_BAD_NUMBER", keyword + ": " + spec->params[i].name + " = '" +
                                                args[i] + "' is not a number");
                    good = false;
                    continue;
                }
                value = v;
            }
            std::string problem = checkParam(spec->params[i], value);
            if (!problem.empty()) {
                error("GNE_PARAMETER", keyword + ": " + problem);
                good = false;
            }
            if (i < args.size()) call.values.push_back(value);
        }
        while (!call.values.empty() && !call.values.back())
            call.values.pop_back();
        if (!good) return;
        if (keyword.rfind("WINDOW_", 0) == 0)
            plane_ = spec->plane;
        else if (!plane_)
            return error("GNE_NO_WINDOW", keyword + " needs a WINDOW_0x before it");
        else if (*plane_ != spec->plane)
            return error("GNE_WRONG_PLANE",
                         keyword + std::string(" belongs to ") +
                             (spec->plane == GnePlane::Turning ? "turning (WINDOW_01)"
                                                               : "milling (WINDOW_02)"));
        GneItem item;
        item.call = std::move(call);
        doc_.items.push_back(std::move(item));
    }

    bool setOnce(std::optional<double>& slot, double value, const std::string& name) {
        if (slot) {
            error("GNE_WORD_TWICE", name + " is written twice");
            return false;
        }
        slot = value;
        return true;
    }

    void readElement(const std::string& keyword, const std::string& rest);
    bool readWord(ContourElement& e, const std::string& token);

    GneDocument doc_;
    std::uint32_t lineNumber_;
    bool open_ = false;
    std::optional<GnePlane> plane_;
};

void Reader::readElement(const std::string& keyword, const std::string& rest) {
    Contour& contour = doc_.items.back().contour;
    ContourElement e;
    e.line = lineNumber_;
    const bool isStart = keyword == "START";
    e.kind = isStart             ? ElementKind::Start
             : keyword == "LINE" ? ElementKind::Line
             : keyword == "CW"   ? ElementKind::ArcCW
             : keyword == "CCW"  ? ElementKind::ArcCCW
             : keyword == "RD"   ? ElementKind::Round
             : keyword == "CF"   ? ElementKind::Chamfer
                                 : ElementKind::Relief;
    if (isStart != contour.elements.empty())
        return error("GNE_START_POSITION", isStart ? "START is the first element and appears once"
                                                   : "a contour begins with START");
    if (e.kind == ElementKind::Round || e.kind == ElementKind::Chamfer) {
        std::string v = trim(rest);
        if (!v.empty() && v[0] == '=') v = trim(v.substr(1));
        double value = 0;
        if (!toNumber(v, value) || value <= 0 || value > kMaxGneValue)
            return error("GNE_BAD_NUMBER", keyword + " needs a positive " +
                                               (e.kind == ElementKind::Round ? "radius" : "width") +
                                               " of at most 1000000");
        (e.kind == ElementKind::Round ? e.radius : e.width) = value;
        contour.elements.push_back(e);
        return;
    }
    std::size_t pos = 0;
    bool good = true;
    while (pos < rest.size()) {
        std::size_t end = rest.find_first_of(" \t", pos);
        if (end == std::string::npos) end = rest.size();
        if (end > pos) good = readWord(e, rest.substr(pos, end - pos)) && good;
        pos = end + 1;
    }
    if (e.kind == ElementKind::Start && !(e.end[0] && e.end[1]))
        return error("GNE_START_POINT", std::string("START needs both coordinates (") +
                                            endLetters(contour.plane)[0] + " and " +
                                            endLetters(contour.plane)[1] + ")");
    if (e.kind == ElementKind::Relief && !(e.radius && e.depth))
        return error("GNE_RELIEF", "RELIEF needs the form (E or F), R (radius) and T (depth)");
    if (good) contour.elements.push_back(e);
}

bool Reader::readWord(ContourElement& e, const std::string& token) {
    const GnePlane plane = doc_.items.back().contour.plane;
    const bool arc = e.kind == ElementKind::ArcCW || e.kind == ElementKind::ArcCCW;
    const std::string name = elementKeyword(e.kind);
    if (e.kind == ElementKind::Relief && (token == "E" || token == "F")) {
        e.reliefForm = token[0];
        return true;
    }
    if (token == "TAN" && (e.kind == ElementKind::Line || arc)) return e.tangent = true;
    if (token.rfind("ALT", 0) == 0 && (e.kind == ElementKind::Line || arc)) {
        double v = 0;
        if (!toNumber(token.substr(3), v) || v < 0 || v > 9 || std::floor(v) != v) {
            error("GNE_BAD_NUMBER", "ALT takes the alternative number 0..9");
            return false;
        }
        e.alternative = static_cast<int>(v);
        return true;
    }
    std::size_t split = 1;
    std::string value = token.substr(split);
    if (!value.empty() && value[0] == '=') value = value.substr(1);
    const char letter = token[0];
    double v = 0;
    if (!toNumber(value, v)) {
        error("GNE_BAD_WORD", name + ": '" + token + "' is not a word of this element");
        return false;
    }
    if (std::fabs(v) > kMaxGneValue) {
        error("GNE_BAD_NUMBER", name + ": '" + token + "' lies beyond +-1000000");
        return false;
    }
    const char* ends = endLetters(plane);
    const char* centres = centreLetters(plane);
    const std::string word(1, letter);
    if (e.kind == ElementKind::Relief) {
        std::optional<double>* slot = letter == 'R'   ? &e.radius
                                      : letter == 'T' ? &e.depth
                                      : letter == 'W' ? &e.width
                                      : letter == 'U' ? &e.faceDepth
                                                      : nullptr;
        if (!slot)
            error("GNE_BAD_WORD", "RELIEF takes E|F, R, T, W and U, not " + word);
        else if (v <= 0)
            error("GNE_BAD_NUMBER", "RELIEF " + word + " must be positive");
        else
            return setOnce(*slot, v, word);
        return false;
    }
    for (int k = 0; k < 2; ++k) {
        if (letter == ends[k]) return setOnce(e.end[k], v, word);
        if (arc && letter == centres[k]) return setOnce(e.centre[k], v, word);
    }
    if (e.kind == ElementKind::Line && letter == 'A') return setOnce(e.angle, v, word);
    if (e.kind == ElementKind::Line && letter == 'L') {
        if (v > 0) return setOnce(e.length, v, word);
        error("GNE_BAD_NUMBER", "L (length) must be positive");
        return false;
    }
    if (arc && letter == 'R') {
        if (v > 0) return setOnce(e.radius, v, word);
        error("GNE_BAD_NUMBER", "R (radius) must be positive");
        return false;
    }
    error("GNE_BAD_WORD", name + " has no word " + word + " in this plane");
    return false;
}

}  // namespace

GneDocument readGne(std::string_view text, std::uint32_t firstLine) {
    return Reader(firstLine).run(text);
}

}  // namespace mtc::core::gne
