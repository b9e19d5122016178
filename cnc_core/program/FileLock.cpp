#include "cnc_core/program/FileLock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "cnc_core/text/Numbers.h"

namespace mtc::core {

FileLock::FileLock(const std::string& guarded, double waitSeconds) {
    const std::string path = guarded + ".lock";
    // O_NOFOLLOW: a link planted as the lock file is refused, not followed.
    const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0) {
        error_ = "cannot open the lock file " + path + ": " + std::strerror(errno);
        return;
    }
    struct stat info {};
    if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
        error_ = "the lock file " + path + " is not a regular file";
        ::close(fd);
        return;
    }
    timespec start{};
    clock_gettime(CLOCK_MONOTONIC, &start);
    for (;;) {
        if (::flock(fd, LOCK_EX | LOCK_NB) == 0) {
            fd_ = fd;
            return;
        }
        if (errno != EWOULDBLOCK && errno != EINTR) {
            error_ = "cannot lock " + path + ": " + std::strerror(errno);
            break;
        }
        timespec now{};
        clock_gettime(CLOCK_MONOTONIC, &now);
        const double waited = static_cast<double>(now.tv_sec - start.tv_sec) +
                              static_cast<double>(now.tv_nsec - start.tv_nsec) / 1e9;
        if (waited >= waitSeconds) {
            const std::string seconds = formatGeneral(waitSeconds);
            error_ = guarded + " is being changed by another program (its lock " + path +
                     " was held for " + seconds + " s); try again when it is done";
            break;
        }
        const timespec pause{0, 2 * 1000 * 1000};  // 2 ms
        nanosleep(&pause, nullptr);
    }
    ::close(fd);
}

FileLock::~FileLock() {
    if (fd_ >= 0) ::close(fd_);  // closing releases the flock
}

}  // namespace mtc::core
