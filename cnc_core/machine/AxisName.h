#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace mtc::core {

/// An axis designation as programs write it: a letter (X Y Z U V W A B C) plus
/// an optional index 1..3 ("Z2", "Y1"); index 0 means "no index" ("X").
struct AxisName {
    char letter = 0;
    std::uint8_t index = 0;

    bool valid() const { return letter != 0; }
    bool operator==(const AxisName& other) const {
        return letter == other.letter && index == other.index;
    }
    bool operator!=(const AxisName& other) const { return !(*this == other); }

    /// "Z2", "X", "" for an invalid name.
    std::string toString() const;
    /// Parses "X", "Z2", "c1" (case-insensitive letter). Returns an invalid
    /// name for anything else (empty text, index > 3, trailing characters).
    static AxisName parse(std::string_view text);
};

/// The nine axis definitions (axis functionality, Cxx.053) in seed order:
/// linear main X Y Z, secondary U V W, rotary main A B C.
enum class AxisDefinition : std::int8_t { None = -1, X, Y, Z, U, V, W, A, B, C };

inline constexpr int kDefinitionCount = 9;

/// 'X'..'C' -> definition; AxisDefinition::None for any other letter.
AxisDefinition definitionFromLetter(char letter);
/// Definition -> 'X'..'C'; '-' for None.
char definitionLetter(AxisDefinition definition);
/// X, Y and Z are the linear main axes that span the coordinate system.
inline bool isMainDefinition(AxisDefinition d) {
    return d == AxisDefinition::X || d == AxisDefinition::Y || d == AxisDefinition::Z;
}

}  // namespace mtc::core
