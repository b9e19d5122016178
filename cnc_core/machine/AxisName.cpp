#include "cnc_core/machine/AxisName.h"

#include <cctype>

namespace mtc::core {

std::string AxisName::toString() const {
    if (!valid()) return {};
    std::string text(1, letter);
    if (index > 0) text += static_cast<char>('0' + index);
    return text;
}

AxisName AxisName::parse(std::string_view text) {
    if (text.empty() || text.size() > 2) return {};
    const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])));
    if (letter < 'A' || letter > 'Z') return {};
    AxisName name{letter, 0};
    if (text.size() == 2) {
        if (text[1] < '1' || text[1] > '3') return {};
        name.index = static_cast<std::uint8_t>(text[1] - '0');
    }
    return name;
}

AxisDefinition definitionFromLetter(char letter) {
    switch (std::toupper(static_cast<unsigned char>(letter))) {
        case 'X':
            return AxisDefinition::X;
        case 'Y':
            return AxisDefinition::Y;
        case 'Z':
            return AxisDefinition::Z;
        case 'U':
            return AxisDefinition::U;
        case 'V':
            return AxisDefinition::V;
        case 'W':
            return AxisDefinition::W;
        case 'A':
            return AxisDefinition::A;
        case 'B':
            return AxisDefinition::B;
        case 'C':
            return AxisDefinition::C;
        default:
            return AxisDefinition::None;
    }
}

char definitionLetter(AxisDefinition definition) {
    static constexpr char kLetters[] = "XYZUVWABC";
    if (definition == AxisDefinition::None) return '-';
    return kLetters[static_cast<int>(definition)];
}

}  // namespace mtc::core
