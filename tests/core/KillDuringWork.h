#pragma once

// Kills a forked worker at a random moment of its work, but only after it
// has finished one step: on a busy machine a save (two fsyncs) can take
// longer than the random delay, and a test whose kills all land before the
// first finished step proves nothing.
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

namespace mtc::test {

/// Called in the child after every finished step.
inline void stepDone(int fd) {
    const char done = 1;
    if (::write(fd, &done, 1) != 1) ::_exit(4);
}

/// Forks `work(fd)` (which calls stepDone(fd) after each step and never
/// returns), waits up to 60 s for its first finished step, lets it go on
/// for `delayMicroseconds`, kills it with SIGKILL and reaps it. Returns true
/// when the child was killed (not ended by itself) after a finished step.
template <class Work>
bool killDuringWork(Work work, int delayMicroseconds) {
    int fds[2];
    if (::pipe(fds) != 0) return false;
    const pid_t child = ::fork();
    if (child < 0) return false;
    if (child == 0) {
        ::close(fds[0]);
        work(fds[1]);
        ::_exit(5);
    }
    ::close(fds[1]);
    pollfd wait{fds[0], POLLIN, 0};
    const bool stepped = ::poll(&wait, 1, 60000) == 1;
    if (stepped) ::usleep(static_cast<useconds_t>(delayMicroseconds));
    ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    ::close(fds[0]);
    EXPECT_TRUE(WIFSIGNALED(status)) << "the worker stopped by itself (exit "
                                     << WEXITSTATUS(status) << ")";
    return stepped && WIFSIGNALED(status);
}

}  // namespace mtc::test
