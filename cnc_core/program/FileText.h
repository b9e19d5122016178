#pragma once

#include <cstddef>
#include <string>

namespace mtc::core {

/// Why `path` is not a regular file one can read, as the end of a sentence
/// ("does not exist", "is a directory", "is a FIFO", "is a device", "is a
/// socket", "cannot be examined: <reason>"); "" when it is a regular file
/// (a symbolic link counts as what it points to). Changes nothing.
std::string whyNotARegularFile(const std::string& path);

/// Reads the whole regular file `path` into `text` with a single allocation
/// of its size (program files can be large; no stream buffer copy). Returns
/// false (and `error` says why, naming the path; `text` is then empty) when
/// the path is not a readable regular file or larger than `maxBytes`. A FIFO
/// or device is refused without being opened for a blocking read.
bool readFileText(const std::string& path, std::string& text, std::string& error,
                  std::size_t maxBytes = std::size_t(1) << 31);

}  // namespace mtc::core
