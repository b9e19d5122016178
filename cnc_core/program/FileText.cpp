#include "cnc_core/program/FileText.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace mtc::core {
namespace {

/// What a stat mode that is not a regular file is.
std::string kindOf(mode_t mode) {
    if (S_ISDIR(mode)) return "is a directory";
    if (S_ISFIFO(mode)) return "is a FIFO (named pipe)";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device";
    if (S_ISSOCK(mode)) return "is a socket";
    return "is not a regular file";
}

}  // namespace

std::string whyNotARegularFile(const std::string& path) {
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0)
        return errno == ENOENT ? "does not exist"
                               : std::string("cannot be examined: ") + std::strerror(errno);
    return S_ISREG(info.st_mode) ? std::string() : kindOf(info.st_mode);
}

bool readFileText(const std::string& path, std::string& text, std::string& error,
                  std::size_t maxBytes) {
    text.clear();
    // O_NONBLOCK: opening a FIFO must not wait for a writer; fstat decides.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        const std::string why = whyNotARegularFile(path);
        error = path + ": " + (why.empty() ? std::string("cannot be read: ") + std::strerror(errno)
                                           : why);
        return false;
    }
    struct stat info {};
    if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
        error = path + ": " + kindOf(info.st_mode);
        ::close(fd);
        return false;
    }
    if (static_cast<std::size_t>(info.st_size) > maxBytes) {
        error = path + ": is larger than " + std::to_string(maxBytes >> 20) + " MiB";
        ::close(fd);
        return false;
    }
    text.resize(static_cast<std::size_t>(info.st_size) + 1);  // +1: the end is seen at once
    std::size_t read = 0;
    bool failed = false;
    for (;;) {  // a file that grew while reading: take the rest too (up to maxBytes)
        if (read == text.size()) text.resize(read + 65536);
        const ssize_t n = ::read(fd, text.data() + read, text.size() - read);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            failed = n < 0;
            break;
        }
        read += static_cast<std::size_t>(n);
        if (read > maxBytes) break;
    }
    const int readErrno = errno;
    ::close(fd);
    text.resize(read);
    if (failed || read > maxBytes) {
        text.clear();
        error = path + (failed ? ": cannot be read: " + std::string(std::strerror(readErrno))
                               : ": grew beyond " + std::to_string(maxBytes >> 20) + " MiB");
        return false;
    }
    return true;
}

}  // namespace mtc::core
