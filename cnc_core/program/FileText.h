#pragma once

#include <string>

namespace mtc::core {

/// Reads the whole regular file `path` into `text` with a single allocation
/// of its size (program files can be large; no stream buffer copy). Returns
/// false (and `error` says why; `text` is then empty) when the path is not a
/// readable regular file.
bool readFileText(const std::string& path, std::string& text, std::string& error);

}  // namespace mtc::core
