#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace mtc::core {

/// Replaces the file `path` with `data` atomically: writes a temporary file
/// `<file>.tmpXXXXXX` in the same directory, flushes it to disk (fsync),
/// renames it over the file and syncs the directory. Readers see either the
/// old or the new file, never a partial one. Every file the product writes
/// goes through here (docs/decisions/config-files.md CF-010..CF-013):
/// - a target that exists and is not a regular file (directory, FIFO,
///   device, socket) is refused: nothing is written, nothing is replaced;
/// - a symbolic link is written through: its real file gets the new
///   content (and is created where the link points if it does not exist
///   yet), the link stays a link; a loop of links or a link into a missing
///   directory is refused;
/// - a read-only target (no write permission bit, or not writable for this
///   user) is refused, also for root, with a message that says how to go on;
/// - the new file keeps the mode (and, where allowed, the owner) of the old.
/// Returns false (and `error` says why, naming the path; the temporary file
/// is removed, `path` is untouched) when anything is refused or fails.
bool writeFileAtomically(const std::string& path, std::string_view data, std::string& error);

/// What writeFileAtomically() checks before it writes anything: true when
/// `path` does not exist or is (or links to) a writable regular file; false
/// with the same message otherwise. For callers that remove or replace
/// several files together and must refuse before the first change.
bool checkReplaceable(const std::string& path, std::string& error);

/// Removes the file `path` when it is there (true also when it was not);
/// for a symbolic link the real file is removed and the link stays, so the
/// next writeFileAtomically() through it creates the file again. False with
/// `error` when it cannot be removed.
bool removeFile(const std::string& path, std::string& error);

/// True when `a` and `b` name the same existing file (same device and inode,
/// after following symbolic links): `X.DAT` and `./x/../X.DAT` or a link to it.
bool sameFile(const std::string& a, const std::string& b);

/// The temporary files `<name>.tmpXXXXXX` of writeFileAtomically in
/// `directory` that a killed save left behind and that are older than
/// `minimumAgeSeconds` (a younger one may belong to a save running in
/// another program), for the names `belongs` accepts (the `<name>` part).
/// Removes them and returns their paths.
std::vector<std::string> removeStaleTemporaries(const std::string& directory,
                                                const std::function<bool(std::string_view)>& belongs,
                                                long minimumAgeSeconds = 60);

}  // namespace mtc::core
