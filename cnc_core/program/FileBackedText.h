#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "cnc_core/language/SourceText.h"

namespace mtc::core {

/// A program file's text kept out of memory where nobody reads it
/// (docs/decisions/process.md, PROC-003). The text lives in an anonymous
/// reservation of the file's size, filled by pread in chunks of kChunkBytes:
/// read just ahead of the parse's line scanner (the counts before the parse
/// read the file through a small buffer), released behind it (so a large
/// program's text is not resident when its words and blocks are);
/// afterwards a chunk is read again on first use and
/// then stays, so a view into it stays valid as long as the text lives. The
/// file stays open. Each chunk's hash is taken when it is first read; a
/// chunk read again with another hash, or cut short, becomes blanks and
/// changed() is set: a file changed or truncated on disk never shows another
/// text under the program's spans, and nothing can fault (the file itself is
/// not mapped).
class FileBackedText final : public ChunkedText {
  public:
    static constexpr std::uint32_t kChunkBytes = std::uint32_t{1} << 16;

    /// Opens the regular file `path` (refused like readFileText: not a
    /// regular file, larger than `maxBytes` or than 4 GiB). Reads nothing
    /// yet. On failure returns nullptr and `error` names the path.
    static std::shared_ptr<FileBackedText> open(const std::string& path, std::string& error,
                                                std::size_t maxBytes = std::size_t(1) << 31);
    ~FileBackedText() override;

    const std::string& path() const override { return path_; }
    std::uint32_t size() const override { return size_; }
    std::string_view read(std::uint32_t offset, std::uint32_t length) const override;
    bool changed() const override { return changed_.load(std::memory_order_acquire); }
    std::string changeMessage() const override;

    bool takeParseWindow() override;
    const char* parseBytes() const override { return bytes_; }
    std::uint32_t fillLinesFrom(std::uint32_t pos) override;
    void releaseBefore(std::uint32_t pos) override;
    void countLinesAndBlanks(std::size_t& lines, std::size_t& blanks) const override;
    void endParse() override;

    std::size_t residentBytes() const override;

  private:
    FileBackedText(std::string path, int descriptor, std::uint32_t size, char* bytes,
                   std::size_t reserved);
    std::uint32_t chunkCount() const {
        return static_cast<std::uint32_t>((std::uint64_t{size_} + kChunkBytes - 1) / kChunkBytes);
    }
    std::uint32_t chunkLength(std::uint32_t chunk) const;
    /// Reads chunk `chunk` from the file into the reservation; false (the
    /// chunk then holds blanks from the first byte not read) on a short read.
    bool readChunk(std::uint32_t chunk) const;
    /// Fills a chunk the parse released (or never reached), under mutex_.
    void refill(std::uint32_t chunk) const;
    void markChanged(std::uint32_t offset) const;
    void release(std::uint32_t firstChunk, std::uint32_t endChunk);

    const std::string path_;
    const int descriptor_;
    const std::uint32_t size_;
    char* const bytes_;
    const std::size_t reserved_;
    /// Per chunk: 1 when its bytes are in memory (set after the fill,
    /// release order; read with acquire order without the mutex).
    std::unique_ptr<std::atomic<std::uint8_t>[]> filled_;
    /// Per chunk: the hash of the bytes the parse read (valid once read).
    mutable std::vector<std::uint64_t> hashes_;
    mutable std::vector<std::uint8_t> hashed_;
    mutable std::mutex mutex_;
    mutable std::atomic<bool> changed_{false};
    mutable std::uint32_t firstChangedOffset_ = 0;
    // The parse window: chunks [released_, reached_) are in memory.
    std::atomic<bool> windowTaken_{false};
    std::uint32_t released_ = 0;
    std::uint32_t reached_ = 0;
    std::uint32_t lastNewline_ = kWholeText;  ///< last '\n' the window holds
};

/// 64-bit hash of `length` bytes (four xxHash64 lanes; for change checks,
/// not against an adversary).
std::uint64_t chunkHash(const char* bytes, std::size_t length);

}  // namespace mtc::core
