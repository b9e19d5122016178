#include "cnc_core/program/FileBackedText.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <limits>

#include "cnc_core/program/FileText.h"

namespace mtc::core {

namespace {

constexpr std::uint64_t kPrime1 = 0x9E3779B185EBCA87ull;
constexpr std::uint64_t kPrime2 = 0xC2B2AE3D27D4EB4Full;
constexpr std::uint64_t kPrime3 = 0x165667B19E3779F9ull;
constexpr std::uint64_t kPrime4 = 0x85EBCA77C2B2AE63ull;
constexpr std::uint64_t kPrime5 = 0x27D4EB2F165667C5ull;

std::uint64_t rotateLeft(std::uint64_t value, int bits) {
    return (value << bits) | (value >> (64 - bits));
}

std::uint64_t load64(const char* bytes) {
    std::uint64_t value = 0;
    std::memcpy(&value, bytes, sizeof value);
    return value;
}

std::uint64_t round64(std::uint64_t lane, std::uint64_t input) {
    return rotateLeft(lane + input * kPrime2, 31) * kPrime1;
}

std::uint64_t mergeLane(std::uint64_t hash, std::uint64_t lane) {
    return (hash ^ round64(0, lane)) * kPrime1 + kPrime4;
}

/// Released chunks go back to the system in runs of at least this many
/// (one madvise per megabyte).
constexpr std::uint32_t kReleaseRun = 16;

/// Reads `length` bytes at `offset`; returns how many it got (short only at
/// the file's end or on an error).
std::size_t readAt(int descriptor, char* into, std::size_t length, std::uint64_t offset) {
    std::size_t got = 0;
    while (got < length) {
        const ssize_t n =
            ::pread(descriptor, into + got, length - got, static_cast<off_t>(offset + got));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        got += static_cast<std::size_t>(n);
    }
    return got;
}

}  // namespace

std::uint64_t chunkHash(const char* bytes, std::size_t length) {
    // xxHash64 (Yann Collet's public algorithm), seed 0.
    const char* p = bytes;
    const char* const end = bytes + length;
    std::uint64_t hash = 0;
    if (length >= 32) {
        std::uint64_t lane1 = kPrime1 + kPrime2, lane2 = kPrime2, lane3 = 0, lane4 = 0 - kPrime1;
        for (; p + 32 <= end; p += 32) {
            lane1 = round64(lane1, load64(p));
            lane2 = round64(lane2, load64(p + 8));
            lane3 = round64(lane3, load64(p + 16));
            lane4 = round64(lane4, load64(p + 24));
        }
        hash = rotateLeft(lane1, 1) + rotateLeft(lane2, 7) + rotateLeft(lane3, 12) +
               rotateLeft(lane4, 18);
        hash = mergeLane(mergeLane(mergeLane(mergeLane(hash, lane1), lane2), lane3), lane4);
    } else {
        hash = kPrime5;
    }
    hash += length;
    for (; p + 8 <= end; p += 8)
        hash = rotateLeft(hash ^ round64(0, load64(p)), 27) * kPrime1 + kPrime4;
    for (; p < end; ++p)
        hash = rotateLeft(hash ^ (static_cast<unsigned char>(*p) * kPrime5), 11) * kPrime1;
    hash ^= hash >> 33;
    hash *= kPrime2;
    hash ^= hash >> 29;
    hash *= kPrime3;
    return hash ^ (hash >> 32);
}

std::shared_ptr<FileBackedText> FileBackedText::open(const std::string& path, std::string& error,
                                                     std::size_t maxBytes) {
    const int descriptor = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (descriptor < 0) {
        const std::string why = whyNotARegularFile(path);
        error = path + ": " +
                (why.empty() ? std::string("cannot be read: ") + std::strerror(errno) : why);
        return nullptr;
    }
    struct stat info {};
    if (::fstat(descriptor, &info) != 0 || !S_ISREG(info.st_mode)) {
        error = path + ": " + whyNotARegularFile(path);
        ::close(descriptor);
        return nullptr;
    }
    const auto bytes = static_cast<std::uint64_t>(info.st_size);
    if (bytes > maxBytes || bytes >= std::numeric_limits<std::uint32_t>::max() - 1) {
        error = path + ": is larger than " + std::to_string(maxBytes >> 20) + " MiB";
        ::close(descriptor);
        return nullptr;
    }
    // One byte more than the text: the parser reads the '\0' after it.
    const std::size_t reserved = static_cast<std::size_t>(bytes) + 1;
    void* memory = ::mmap(nullptr, reserved, PROT_READ | PROT_WRITE,
                          MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (memory == MAP_FAILED) {
        error = path + ": cannot be read: " + std::strerror(errno);
        ::close(descriptor);
        return nullptr;
    }
    return std::shared_ptr<FileBackedText>(new FileBackedText(
        path, descriptor, static_cast<std::uint32_t>(bytes), static_cast<char*>(memory), reserved));
}

FileBackedText::FileBackedText(std::string path, int descriptor, std::uint32_t size, char* bytes,
                               std::size_t reserved)
    : path_(std::move(path)),
      descriptor_(descriptor),
      size_(size),
      bytes_(bytes),
      reserved_(reserved),
      filled_(new std::atomic<std::uint8_t>[chunkCount()]),
      hashes_(chunkCount(), 0),
      hashed_(chunkCount(), 0) {
    for (std::uint32_t chunk = 0; chunk < chunkCount(); ++chunk)
        filled_[chunk].store(0, std::memory_order_relaxed);
}

FileBackedText::~FileBackedText() {
    ::munmap(bytes_, reserved_);
    ::close(descriptor_);
}

std::uint32_t FileBackedText::chunkLength(std::uint32_t chunk) const {
    const std::uint32_t offset = chunk * kChunkBytes;
    return std::min(kChunkBytes, size_ - offset);
}

bool FileBackedText::readChunk(std::uint32_t chunk) const {
    const std::uint32_t offset = chunk * kChunkBytes;
    const std::uint32_t length = chunkLength(chunk);
    char* const into = bytes_ + offset;
    const std::size_t got = readAt(descriptor_, into, length, offset);
    if (got < length) std::memset(into + got, ' ', length - got);
    return got == length;
}

void FileBackedText::refill(std::uint32_t chunk) const {
    std::lock_guard<std::mutex> lock(mutex_);
    if (filled_[chunk].load(std::memory_order_relaxed)) return;
    const bool whole = readChunk(chunk);
    const std::uint32_t offset = chunk * kChunkBytes;
    const std::uint64_t hash = chunkHash(bytes_ + offset, chunkLength(chunk));
    if (!hashed_[chunk]) {  // the first read: the text the spans refer to
        hashes_[chunk] = hash;
        hashed_[chunk] = 1;
    } else if (hash != hashes_[chunk]) {
        std::memset(bytes_ + offset, ' ', chunkLength(chunk));
        markChanged(offset);
    }
    if (!whole) markChanged(offset);
    filled_[chunk].store(1, std::memory_order_release);
}

void FileBackedText::markChanged(std::uint32_t offset) const {
    if (changed_.load(std::memory_order_relaxed) && firstChangedOffset_ <= offset) return;
    firstChangedOffset_ = offset;
    changed_.store(true, std::memory_order_release);
}

std::string FileBackedText::changeMessage() const {
    if (!changed()) return {};
    std::lock_guard<std::mutex> lock(mutex_);
    return path_ + " changed on disk while the program was in use: its text from byte " +
           std::to_string(firstChangedOffset_) +
           " on could not be read again as it was loaded and reads as blanks; load the "
           "program again";
}

std::string_view FileBackedText::read(std::uint32_t offset, std::uint32_t length) const {
    offset = std::min(offset, size_);
    length = std::min(length, size_ - offset);
    if (length > 0) {
        const std::uint32_t last = (offset + length - 1) / kChunkBytes;
        for (std::uint32_t chunk = offset / kChunkBytes; chunk <= last; ++chunk)
            if (!filled_[chunk].load(std::memory_order_acquire)) refill(chunk);
    }
    return std::string_view(bytes_ + offset, length);
}

bool FileBackedText::takeParseWindow() {
    return !windowTaken_.exchange(true);
}

std::uint32_t FileBackedText::fillLinesFrom(std::uint32_t pos) {
    while (reached_ < chunkCount() && (lastNewline_ == kWholeText || lastNewline_ < pos)) {
        const std::uint32_t chunk = reached_++;
        refill(chunk);
        const char* begin = bytes_ + std::size_t{chunk} * kChunkBytes;
        const void* newline = ::memrchr(begin, '\n', chunkLength(chunk));
        if (newline)
            lastNewline_ = static_cast<std::uint32_t>(static_cast<const char*>(newline) - bytes_);
    }
    if (reached_ == chunkCount()) return kWholeText;
    return lastNewline_ == kWholeText ? 0 : lastNewline_ + 1;
}

void FileBackedText::releaseBefore(std::uint32_t pos) {
    const std::uint32_t end = std::min(pos / kChunkBytes, reached_);
    if (end >= released_ + kReleaseRun) release(released_, end);
}

void FileBackedText::release(std::uint32_t firstChunk, std::uint32_t endChunk) {
    if (endChunk <= firstChunk) return;
    std::lock_guard<std::mutex> lock(mutex_);
    for (std::uint32_t chunk = firstChunk; chunk < endChunk; ++chunk)
        filled_[chunk].store(0, std::memory_order_relaxed);
    char* const begin = bytes_ + std::size_t{firstChunk} * kChunkBytes;
    const std::size_t length = std::size_t{endChunk - firstChunk} * kChunkBytes;
    // Whole pages only: the last chunk may end inside the reservation's last page.
    const std::size_t bytes =
        std::min(length, reserved_ - static_cast<std::size_t>(begin - bytes_));
    ::madvise(begin, bytes, MADV_DONTNEED);
    released_ = std::max(released_, endChunk);
}

void FileBackedText::endParse() {
    release(released_, reached_);
}

void FileBackedText::countLinesAndBlanks(std::size_t& lines, std::size_t& blanks) const {
    // The counts only size the parse's reservations, so they are taken from
    // a read of each chunk into one small buffer that stays in the cache;
    // the text itself is read into the reservation just ahead of the parse
    // (fillLinesFrom), which then finds it in the cache too. Reading the
    // whole text in here instead made the parse read it back from memory
    // (docs/decisions/process.md, PROC-004). A file that changes between
    // the two reads only gives counts that do not fit: the parse grows its
    // lists then; the text the spans refer to is the one the parse read.
    std::vector<char> buffer(kChunkBytes);
    for (std::uint32_t chunk = 0; chunk < chunkCount(); ++chunk) {
        const std::size_t got = readAt(descriptor_, buffer.data(), chunkLength(chunk),
                                       std::uint64_t{chunk} * kChunkBytes);
        mtc::core::countLinesAndBlanks(std::string_view(buffer.data(), got), lines, blanks);
    }
}

std::size_t FileBackedText::residentBytes() const {
    std::size_t bytes = 0;
    for (std::uint32_t chunk = 0; chunk < chunkCount(); ++chunk)
        if (filled_[chunk].load(std::memory_order_acquire)) bytes += chunkLength(chunk);
    return bytes;
}

}  // namespace mtc::core
