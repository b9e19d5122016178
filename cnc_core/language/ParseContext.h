#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "cnc_core/language/Program.h"

namespace mtc::core {

/// State shared by the parts of one parseProgram() run: the program being
/// built, the diagnostic budget and the macros defined so far. Internal to
/// the language layer.
class ParseContext {
  public:
    /// Most diagnostics one parse records; garbage input cannot flood memory.
    static constexpr std::size_t kMaxDiagnostics = 1000;

    explicit ParseContext(Program& program, bool plainBlockFastPath = true)
        : program_(program), plainBlockFastPath_(plainBlockFastPath) {}

    Program& program() { return program_; }
    /// The text being parsed, followed by a '\0'. Through a file's window
    /// (ChunkedText) only the lines readyLinesFrom() made ready may be read.
    std::string_view source() const { return text_; }
    /// Parses `text`; `window` (or nullptr) is the ChunkedText it lies in.
    void useText(std::string_view text, ChunkedText* window) {
        text_ = text;
        window_ = window;
    }
    /// Makes the lines from `pos` on readable; returns the offset below
    /// which every line start has its whole line ready (ChunkedText::
    /// kWholeText for an owned text).
    std::uint32_t readyLinesFrom(std::uint32_t pos) {
        return window_ ? window_->fillLinesFrom(pos) : ChunkedText::kWholeText;
    }
    /// The text before `pos` will not be read again by the parse.
    void doneBefore(std::uint32_t pos) {
        if (window_) window_->releaseBefore(pos);
    }

    /// Records a diagnostic at `line`:`column` of block `block` ("N0012" or
    /// ""). After kMaxDiagnostics it records one PARSE_TOO_MANY_DIAGNOSTICS
    /// error and drops the rest.
    void report(Severity severity, const char* code, std::uint32_t line, std::uint32_t column,
                std::string block, std::string message);

    /// Macro names defined by DEFINE so far (seed 001, ch. 4).
    const std::vector<std::string>& macros() const { return macros_; }
    void addMacro(std::string_view name);
    /// Bit c - 'A' set: some macro name starts with the letter c.
    std::uint32_t macroLetters() const { return macroLetters_; }
    /// True when `name` is one of macros(). Names whose length or first
    /// letter no macro has are refused at once (the name scan asks for
    /// every name of every block).
    bool isMacro(std::string_view name) const {
        if (name.size() < shortestMacro_ || name.size() > longestMacro_) return false;
        const unsigned letter = name.empty() ? 26 : static_cast<unsigned char>(name[0]) - 'A';
        if (letter < 26 && !((macroLetters_ >> letter) & 1u)) return false;
        return findMacro(name);
    }
    /// Whether the parser may take plain blocks by its fast path.
    bool plainBlockFastPath() const { return plainBlockFastPath_; }

  private:
    Program& program_;
    std::string_view text_;
    ChunkedText* window_ = nullptr;
    bool plainBlockFastPath_ = true;
    std::size_t reported_ = 0;
    bool findMacro(std::string_view name) const;

    std::vector<std::string> macros_;
    /// Bit c - 'A' set: a macro name starts with c; names starting with
    /// another byte are not filtered by their first letter.
    std::uint32_t macroLetters_ = 0;
    std::size_t shortestMacro_ = static_cast<std::size_t>(-1);
    std::size_t longestMacro_ = 0;
};

/// "N0012" / "N0012:0003" / "" (number < 0).
std::string formatBlockId(std::int32_t number, std::int32_t subNumber = -1);

}  // namespace mtc::core
