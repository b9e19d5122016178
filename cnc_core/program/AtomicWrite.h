#pragma once

#include <string>
#include <string_view>

namespace mtc::core {

/// Replaces the file `path` with `data` atomically: writes a temporary file
/// in the same directory, flushes it to disk (fsync), renames it over `path`
/// and syncs the directory. Readers see either the old or the new file, never
/// a partial one. Returns false (and `error` says why; the temporary file is
/// removed, `path` is untouched) when any step fails.
bool writeFileAtomically(const std::string& path, std::string_view data, std::string& error);

}  // namespace mtc::core
