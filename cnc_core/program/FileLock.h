#pragma once

#include <string>

namespace mtc::core {

/// An exclusive advisory lock (flock) on a lock file beside the file it
/// guards (`<file>.lock`, created when missing and left in place: it is
/// never renamed, so every program locks the same inode whatever atomic
/// saves do to the file itself). One writer at a time for read-modify-write
/// (docs/decisions/config-files.md CF-020). Released by the destructor, and
/// by the system when the process dies.
class FileLock {
  public:
    /// Longest wait for the lock by default.
    static constexpr double kDefaultWaitSeconds = 5.0;

    /// Locks `<guarded>.lock`, waiting at most `waitSeconds`. locked() says
    /// whether it worked; error() says why not ("... is being changed by
    /// another program (waited 5 s)", or why the lock file cannot be made).
    explicit FileLock(const std::string& guarded, double waitSeconds = kDefaultWaitSeconds);
    ~FileLock();
    FileLock(const FileLock&) = delete;
    FileLock& operator=(const FileLock&) = delete;

    bool locked() const { return fd_ >= 0; }
    const std::string& error() const { return error_; }

  private:
    int fd_ = -1;
    std::string error_;
};

}  // namespace mtc::core
