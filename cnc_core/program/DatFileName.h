#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace mtc::core {

/// What a program file name `NuxxYzzz.DAT` says (seed 001, ch. 10):
/// u plant address 0-9/A-F, xx package 01-99, y process 0-6, zzz program 001-099.
struct DatFileName {
    int plant = 0;    ///< 0..15 (written as one hex digit)
    int package = 1;  ///< 1..99
    int process = 0;  ///< 0..6
    int number = 1;   ///< 1..99
};

/// Parses the last path component of `path` as `NuxxYzzz.DAT` (extension in
/// any letter case). Returns nothing when the name does not follow the
/// naming or a field is out of range; `whyNot` (if given) then says why.
std::optional<DatFileName> parseDatFileName(std::string_view path, std::string* whyNot = nullptr);

/// Forms "NuxxYzzz.DAT". Returns "" when a field is out of range.
std::string formatDatFileName(const DatFileName& name);

}  // namespace mtc::core
