#include "cnc_core/program/AtomicWrite.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

namespace mtc::core {

namespace {

std::string directoryOf(const std::string& path) {
    std::size_t slash = path.find_last_of('/');
    if (slash == std::string::npos) return ".";
    if (slash == 0) return "/";
    return path.substr(0, slash);
}

bool writeAll(int fd, std::string_view data) {
    const char* p = data.data();
    std::size_t left = data.size();
    while (left > 0) {
        ssize_t written = ::write(fd, p, left);
        if (written < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        p += written;
        left -= static_cast<std::size_t>(written);
    }
    return true;
}

std::string describe(const char* step, const std::string& path) {
    return std::string(step) + " " + path + ": " + std::strerror(errno);
}

}  // namespace

bool writeFileAtomically(const std::string& path, std::string_view data, std::string& error) {
    std::string pattern = path + ".tmpXXXXXX";
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    int fd = ::mkstemp(name.data());
    if (fd < 0) {
        error = describe("cannot create a temporary file for", path);
        return false;
    }
    std::string temporary(name.data());
    bool ok = writeAll(fd, data);
    if (!ok) error = describe("cannot write", temporary);
    if (ok && ::fsync(fd) != 0) {
        error = describe("cannot flush", temporary);
        ok = false;
    }
    if (::close(fd) != 0 && ok) {
        error = describe("cannot close", temporary);
        ok = false;
    }
    if (ok) {
        // Keep the permissions of the file being replaced (mkstemp uses 0600).
        struct stat existing {};
        ::chmod(temporary.c_str(),
                ::stat(path.c_str(), &existing) == 0 ? existing.st_mode & 07777 : 0644);
    }
    if (ok && std::rename(temporary.c_str(), path.c_str()) != 0) {
        error = describe("cannot rename the temporary file to", path);
        ok = false;
    }
    if (!ok) {
        ::unlink(temporary.c_str());
        return false;
    }
    int directory = ::open(directoryOf(path).c_str(), O_RDONLY | O_DIRECTORY);
    if (directory >= 0) {
        ::fsync(directory);  // the rename itself is durable only after this
        ::close(directory);
    }
    return true;
}

}  // namespace mtc::core
