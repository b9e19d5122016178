#include "cnc_core/contour/StrokeFont.h"

#include <cctype>
#include <cstdlib>
#include <cstring>

#include "cnc_core/text/Numbers.h"

namespace mtc::core::gne {
namespace {

struct Glyph {
    char c;
    const char* strokes;  ///< "x,y x,y|x,y x,y" in grid units
};

// clang-format off
constexpr Glyph kGlyphs[] = {
    {'A', "0,0 0,4 2,6 4,4 4,0|0,3 4,3"},
    {'B', "0,0 0,6 3,6 4,5 4,4 3,3 0,3|3,3 4,2 4,1 3,0 0,0"},
    {'C', "4,1 3,0 1,0 0,1 0,5 1,6 3,6 4,5"},
    {'D', "0,0 0,6 2,6 4,4 4,2 2,0 0,0"},
    {'E', "4,0 0,0 0,6 4,6|0,3 3,3"},
    {'F', "0,0 0,6 4,6|0,3 3,3"},
    {'G', "4,5 3,6 1,6 0,5 0,1 1,0 3,0 4,1 4,3 2,3"},
    {'H', "0,0 0,6|4,0 4,6|0,3 4,3"},
    {'I', "1,0 3,0|2,0 2,6|1,6 3,6"},
    {'J', "0,1 1,0 2,0 3,1 3,6"},
    {'K', "0,0 0,6|4,6 0,2|1,3 4,0"},
    {'L', "0,6 0,0 4,0"},
    {'M', "0,0 0,6 2,3 4,6 4,0"},
    {'N', "0,0 0,6 4,0 4,6"},
    {'O', "1,0 0,1 0,5 1,6 3,6 4,5 4,1 3,0 1,0"},
    {'P', "0,0 0,6 3,6 4,5 4,4 3,3 0,3"},
    {'Q', "1,0 0,1 0,5 1,6 3,6 4,5 4,1 3,0 1,0|2,2 4,0"},
    {'R', "0,0 0,6 3,6 4,5 4,4 3,3 0,3|2,3 4,0"},
    {'S', "0,1 1,0 3,0 4,1 4,2 3,3 1,3 0,4 0,5 1,6 3,6 4,5"},
    {'T', "0,6 4,6|2,6 2,0"},
    {'U', "0,6 0,1 1,0 3,0 4,1 4,6"},
    {'V', "0,6 2,0 4,6"},
    {'W', "0,6 1,0 2,3 3,0 4,6"},
    {'X', "0,0 4,6|0,6 4,0"},
    {'Y', "0,6 2,3 4,6|2,3 2,0"},
    {'Z', "0,6 4,6 0,0 4,0"},
    {'0', "1,0 0,1 0,5 1,6 3,6 4,5 4,1 3,0 1,0|0,1 4,5"},
    {'1', "1,5 2,6 2,0|1,0 3,0"},
    {'2', "0,5 1,6 3,6 4,5 4,4 0,0 4,0"},
    {'3', "0,5 1,6 3,6 4,5 4,4 3,3 4,2 4,1 3,0 1,0 0,1|1,3 3,3"},
    {'4', "3,0 3,6 0,2 4,2"},
    {'5', "4,6 0,6 0,3 3,3 4,2 4,1 3,0 0,0"},
    {'6', "3,6 1,6 0,5 0,1 1,0 3,0 4,1 4,2 3,3 0,3"},
    {'7', "0,6 4,6 1,0"},
    {'8', "1,3 0,4 0,5 1,6 3,6 4,5 4,4 3,3 1,3 0,2 0,1 1,0 3,0 4,1 4,2 3,3"},
    {'9', "1,0 3,0 4,1 4,5 3,6 1,6 0,5 0,4 1,3 4,3"},
    {'-', "1,3 3,3"},
    {'+', "1,3 3,3|2,2 2,4"},
    {'.', "2,0 2,0.5"},
    {'/', "0,0 4,6"},
    {':', "2,1 2,1.5|2,4 2,4.5"},
    {' ', ""},
};
// clang-format on

Stroke parseStroke(const char* text, std::size_t length) {
    Stroke stroke;
    const char* p = text;
    const char* last = text + length;
    while (p != last) {
        double x = 0.0;
        double y = 0.0;
        const char* end = readNumberPrefix(p, last, x);
        if (end == p || end == last || *end != ',') break;
        p = end + 1;
        end = readNumberPrefix(p, last, y);
        if (end == p) break;
        stroke.emplace_back(x, y);
        p = end;
        while (p != last && *p == ' ')
            ++p;
    }
    return stroke;
}

}  // namespace

std::vector<Stroke> glyphStrokes(char c, bool* known) {
    const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (known) *known = false;
    for (const Glyph& g : kGlyphs) {
        if (g.c != upper) continue;
        if (known) *known = true;
        std::vector<Stroke> strokes;
        const char* start = g.strokes;
        while (*start) {
            const char* bar = std::strchr(start, '|');
            const std::size_t length =
                bar ? static_cast<std::size_t>(bar - start) : std::strlen(start);
            strokes.push_back(parseStroke(start, length));
            start += length + (bar ? 1 : 0);
        }
        return strokes;
    }
    return {};
}

std::string fontCharacters() {
    std::string all;
    for (const Glyph& g : kGlyphs)
        all += g.c;
    return all;
}

}  // namespace mtc::core::gne
