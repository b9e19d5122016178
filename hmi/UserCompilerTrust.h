#pragma once

#include <QString>

namespace mtc::hmi {

/// The desk's own record of which user compiler commands of program folders
/// may run without asking (docs/DECISIONS.md D-010): commands typed at this
/// desk on the NC options screen, commands the operator approved once after
/// seeing them, and every command of a folder the trainer listed as trusted.
/// Kept in the desk settings (QSettings, group "userCompilers": array
/// "approved" of folder/slot/command, list "trustedFolders"); a folder is
/// named by its canonical path, a command by its exact text.
class UserCompilerTrust {
  public:
    /// True when `command` may run as user compiler `slot` of `folder`
    /// without a question ("" folder = built-in programs: only the operator
    /// can set a command there, so always true).
    static bool approved(const QString& folder, int slot, const QString& command);
    /// Records that `command` of `folder` may run as user compiler `slot`.
    static void approve(const QString& folder, int slot, const QString& command);
    /// True when the trainer listed `folder` (or a folder above it) as trusted.
    static bool folderTrusted(const QString& folder);
    /// Adds `folder` to the trusted folders (the trainer's decision).
    static void trustFolder(const QString& folder);
};

}  // namespace mtc::hmi
