#include "cnc_core/program/AtomicWrite.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>

#include "cnc_core/program/FileText.h"

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

/// The file a write of `path` must replace: `path` itself, or the real
/// file a chain of symbolic links leads to (which may not exist yet: it is
/// created where the last link points). False with `error` when the links
/// loop or lead into a directory that does not exist.
bool realTarget(const std::string& path, std::string& target, std::string& error) {
    target = path;
    for (int depth = 0; depth < 40; ++depth) {
        struct stat link {};
        if (::lstat(target.c_str(), &link) != 0 || !S_ISLNK(link.st_mode)) {
            struct stat folder {};
            if (target != path &&
                (::stat(directoryOf(target).c_str(), &folder) != 0 || !S_ISDIR(folder.st_mode))) {
                error = path + " is a symbolic link into " + directoryOf(target) +
                        ", which is not a directory; nothing written";
                return false;
            }
            return true;
        }
        char next[PATH_MAX];
        const ssize_t length = ::readlink(target.c_str(), next, sizeof next - 1);
        if (length < 0) {
            error = describe("cannot read the symbolic link", path);
            return false;
        }
        const std::string to(next, static_cast<std::size_t>(length));
        target = !to.empty() && to[0] == '/' ? to : directoryOf(target) + "/" + to;
    }
    error = path + " is a loop of symbolic links; nothing written";
    return false;
}

/// "" when `target` may be replaced: it does not exist, or it is a regular
/// file with write permission; else why not (named as `shown`).
std::string whyNotReplaceable(const std::string& target, const std::string& shown,
                              struct stat& existing, bool& exists) {
    exists = ::stat(target.c_str(), &existing) == 0;
    if (!exists) return errno == ENOENT ? "" : describe("cannot examine", shown);
    if (!S_ISREG(existing.st_mode))
        return shown + " " + whyNotARegularFile(target) +
               ", not a regular file; it is not replaced and nothing is written";
    if ((existing.st_mode & 0222) == 0 || ::access(target.c_str(), W_OK) != 0) {
        char mode[8];
        std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(existing.st_mode & 07777));
        return shown + " is read-only (mode " + mode +
               "); it is not replaced: make it writable (chmod u+w) or write to another file";
    }
    return "";
}

}  // namespace

bool writeFileAtomically(const std::string& path, std::string_view data, std::string& error) {
    if (path.empty() || path.back() == '/') {
        error = "'" + path + "' is not a file name";
        return false;
    }
    std::string target;
    if (!realTarget(path, target, error)) return false;
    struct stat existing {};
    bool exists = false;
    error = whyNotReplaceable(target, path, existing, exists);
    if (!error.empty()) return false;
    std::string pattern = target + ".tmpXXXXXX";
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
    // Keep the permissions (and, where allowed, the owner) of the file replaced.
    ::fchmod(fd, exists ? existing.st_mode & 07777 : 0644);
    if (exists && ::fchown(fd, existing.st_uid, existing.st_gid) != 0) {
        // Only root may give a file away; the new file is then the writer's.
    }
    if (ok && ::fsync(fd) != 0) {
        error = describe("cannot flush", temporary);
        ok = false;
    }
    if (::close(fd) != 0 && ok) {
        error = describe("cannot close", temporary);
        ok = false;
    }
    if (ok) {
        // The target may have been replaced by something else meanwhile.
        struct stat again {};
        bool stillExists = false;
        error = whyNotReplaceable(target, path, again, stillExists);
        ok = error.empty();
    }
    if (ok && std::rename(temporary.c_str(), target.c_str()) != 0) {
        error = describe("cannot rename the temporary file to", path);
        ok = false;
    }
    if (!ok) {
        ::unlink(temporary.c_str());
        return false;
    }
    int directory = ::open(directoryOf(target).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (directory >= 0) {
        ::fsync(directory);  // the rename itself is durable only after this
        ::close(directory);
    }
    return true;
}

bool checkReplaceable(const std::string& path, std::string& error) {
    std::string target;
    if (!realTarget(path, target, error)) return false;
    struct stat existing {};
    bool exists = false;
    error = whyNotReplaceable(target, path, existing, exists);
    return error.empty();
}

bool removeFile(const std::string& path, std::string& error) {
    std::string target;
    if (!realTarget(path, target, error)) return false;
    if (std::remove(target.c_str()) == 0 || errno == ENOENT) return true;
    error = describe("cannot remove", path);
    return false;
}

bool sameFile(const std::string& a, const std::string& b) {
    struct stat first {}, second {};
    return ::stat(a.c_str(), &first) == 0 && ::stat(b.c_str(), &second) == 0 &&
           first.st_dev == second.st_dev && first.st_ino == second.st_ino;
}

std::vector<std::string> removeStaleTemporaries(
    const std::string& directory, const std::function<bool(std::string_view)>& belongs,
    long minimumAgeSeconds) {
    std::vector<std::string> removed;
    DIR* dir = ::opendir(directory.empty() ? "." : directory.c_str());
    if (dir == nullptr) return removed;
    const std::time_t now = std::time(nullptr);
    constexpr std::string_view kMark = ".tmp";
    while (const dirent* entry = ::readdir(dir)) {
        const std::string_view name = entry->d_name;
        // "<name>.tmpXXXXXX": mkstemp replaces the six X by letters and digits.
        if (name.size() <= kMark.size() + 6) continue;
        const std::size_t mark = name.size() - 6 - kMark.size();
        if (name.substr(mark, kMark.size()) != kMark || !belongs(name.substr(0, mark))) continue;
        bool random = true;
        for (char c : name.substr(name.size() - 6))
            random = random && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                                (c >= '0' && c <= '9'));
        const std::string path = (directory.empty() ? "." : directory) + "/" + std::string(name);
        struct stat info {};
        if (!random || ::lstat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode) ||
            now - info.st_mtime < minimumAgeSeconds)
            continue;
        if (::unlink(path.c_str()) == 0) removed.push_back(path);
    }
    ::closedir(dir);
    return removed;
}

}  // namespace mtc::core
