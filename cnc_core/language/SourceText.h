#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>

namespace mtc::core {

/// A program text kept in a file and read into memory chunk by chunk
/// (cnc_core/program/FileBackedText.h; docs/decisions/process.md, PROC-003).
/// The parse reads it through a window that is filled ahead of the line
/// scanner and released behind it; afterwards a chunk comes back from the
/// file on first use and stays. A chunk whose bytes differ from those the
/// parse read (the file changed on disk) comes back as blanks, and
/// changed() says so: never another text than the one the spans refer to.
class ChunkedText {
  public:
    virtual ~ChunkedText() = default;
    ChunkedText() = default;
    ChunkedText(const ChunkedText&) = delete;
    ChunkedText& operator=(const ChunkedText&) = delete;

    /// The file the text comes from.
    virtual const std::string& path() const = 0;
    virtual std::uint32_t size() const = 0;
    /// [offset, offset + length) of the text (clamped to the text), read
    /// from the file where it is not in memory. Safe from any thread.
    virtual std::string_view read(std::uint32_t offset, std::uint32_t length) const = 0;
    /// True once a chunk read from the file did not hold the bytes the parse
    /// had read (or the file got shorter): those bytes are blanks.
    virtual bool changed() const = 0;
    /// What changed() means, naming the file; "" while nothing changed.
    virtual std::string changeMessage() const = 0;

    // The parse's window (Parser.cpp): only the first parse of the text
    // takes it; a later parse of the same text reads it whole.
    /// True for the first call only: the caller parses through the window.
    virtual bool takeParseWindow() = 0;
    /// The text's bytes as they are in memory, followed by a '\0': read them
    /// only where fillLinesFrom() made them ready.
    virtual const char* parseBytes() const = 0;
    /// Fills the text on from `pos` (at least one more chunk) until the
    /// filled part holds a '\n' at `pos` or later. Returns the offset below
    /// which every line start has its whole line in memory (through its
    /// '\n'); kWholeText when the text is filled to its end.
    virtual std::uint32_t fillLinesFrom(std::uint32_t pos) = 0;
    /// Releases the memory of the whole chunks before `pos`; the parse does
    /// not read them again.
    virtual void releaseBefore(std::uint32_t pos) = 0;
    /// Counts the text's '\n' and ' ' into `lines` and `blanks` (for the
    /// parse's reservations) without keeping it in memory: the parse reads
    /// it in just ahead of its scanner (fillLinesFrom).
    virtual void countLinesAndBlanks(std::size_t& lines, std::size_t& blanks) const = 0;
    /// The parse is over: releases what the window still holds.
    virtual void endParse() = 0;
    /// Bytes of the text in memory now (whole chunks).
    virtual std::size_t residentBytes() const = 0;

    static constexpr std::uint32_t kWholeText = 0xffffffffu;
};

/// The text every TextSpan of a Program refers to: an owned string (the
/// panel's program memory, the editor, MDI, compiled programs, tests) or a
/// ChunkedText (a program file the headless run reads, PROC-003), shared by
/// the copies of the program.
class SourceText {
  public:
    SourceText() = default;
    SourceText(std::string text) : owned_(std::move(text)) {}  // NOLINT: a string is a text
    SourceText(const char* text) : owned_(text) {}             // NOLINT: a string is a text
    explicit SourceText(std::shared_ptr<ChunkedText> file) : file_(std::move(file)) {}

    std::size_t size() const { return file_ ? file_->size() : owned_.size(); }
    bool empty() const { return size() == 0; }
    /// [offset, offset + length); a file-backed text reads only the chunks
    /// of the span.
    std::string_view span(std::uint32_t offset, std::uint32_t length) const {
        if (!file_) return std::string_view(owned_).substr(offset, length);
        return file_->read(offset, length);
    }
    /// The whole text (a file-backed text is read in whole and stays).
    std::string_view view() const {
        return file_ ? file_->read(0, file_->size()) : std::string_view(owned_);
    }
    operator std::string_view() const { return view(); }  // NOLINT: reads like a string
    /// A copy of the whole text.
    std::string str() const { return std::string(view()); }
    /// The whole text as a string, moved out of an owned text.
    std::string take() && { return file_ ? str() : std::move(owned_); }
    /// Bytes the text holds in memory.
    std::size_t memoryBytes() const { return file_ ? file_->residentBytes() : owned_.capacity(); }
    /// The file behind the text; nullptr for an owned text.
    ChunkedText* file() const { return file_.get(); }

  private:
    std::string owned_;
    std::shared_ptr<ChunkedText> file_;
};

inline bool operator==(const SourceText& text, std::string_view other) {
    return text.view() == other;
}
inline bool operator!=(const SourceText& text, std::string_view other) {
    return !(text == other);
}

/// Counts '\n' and ' ' of `text` into `lines` and `blanks` (added).
void countLinesAndBlanks(std::string_view text, std::size_t& lines, std::size_t& blanks);

}  // namespace mtc::core
