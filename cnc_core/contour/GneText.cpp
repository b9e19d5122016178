#include "cnc_core/contour/GneText.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "cnc_core/contour/GneSchema.h"
#include "cnc_core/text/Numbers.h"

namespace mtc::core::gne {

const char* elementKeyword(ElementKind kind) {
    switch (kind) {
        case ElementKind::Start:
            return "START";
        case ElementKind::Line:
            return "LINE";
        case ElementKind::ArcCW:
            return "CW";
        case ElementKind::ArcCCW:
            return "CCW";
        case ElementKind::Round:
            return "RD";
        case ElementKind::Chamfer:
            return "CF";
        case ElementKind::Relief:
            return "RELIEF";
    }
    return "?";
}

const char* endLetters(GnePlane plane) {
    return plane == GnePlane::Turning ? "ZX" : "XY";
}
const char* centreLetters(GnePlane plane) {
    return plane == GnePlane::Turning ? "KI" : "IJ";
}

/// Longest number the reader takes (GneReader toNumber): plain decimals.
constexpr int kMostDecimals = 38;

std::string formatValue(double value) {
    if (value == 0.0) return "0";
    // Plain decimals only, the fewest that read back as the same double: the
    // reader takes digits, sign and point, no exponent (a value read from
    // 0.0000000001 must not be written as 1e-10, fuzz finding gne 26f6fef).
    std::string text;
    for (int decimals = 0; decimals <= kMostDecimals; ++decimals) {
        text = formatFixed(value, decimals);
        if (leadingNumber(text) == value) break;
    }
    if (text.find('.') != std::string::npos) {
        while (text.back() == '0')
            text.pop_back();
        if (text.back() == '.') text.pop_back();
    }
    return text;
}

namespace {

void word(std::string& out, const char* name, const std::optional<double>& value) {
    if (value) out += std::string(" ") + name + formatValue(*value);
}

}  // namespace

std::string writeElement(const ContourElement& e, GnePlane plane) {
    std::string out = elementKeyword(e.kind);
    const char* ends = endLetters(plane);
    const char* centres = centreLetters(plane);
    switch (e.kind) {
        case ElementKind::Round:
            return out + " " + formatValue(e.radius.value_or(0.0));
        case ElementKind::Chamfer:
            return out + " " + formatValue(e.width.value_or(0.0));
        case ElementKind::Relief:
            out += std::string(" ") + e.reliefForm;
            word(out, "R", e.radius);
            word(out, "T", e.depth);
            word(out, "W", e.width);
            word(out, "U", e.faceDepth);
            return out;
        default:
            break;
    }
    for (int k = 0; k < 2; ++k)
        word(out, std::string(1, ends[k]).c_str(), e.end[k]);
    for (int k = 0; k < 2; ++k)
        word(out, std::string(1, centres[k]).c_str(), e.centre[k]);
    word(out, "A", e.angle);
    word(out, "L", e.length);
    word(out, "R", e.radius);
    if (e.tangent) out += " TAN";
    if (e.alternative != 0) out += " ALT" + std::to_string(e.alternative);
    return out;
}

std::string writeContour(const Contour& c) {
    std::string out = "CONT (" + std::to_string(c.number) + (c.raw ? ", RAW)" : ", FINAL)") + "\n";
    for (const ContourElement& e : c.elements)
        out += writeElement(e, c.plane) + "\n";
    return out + "END_CONT\n";
}

std::string writeCall(const GneCall& call) {
    const CallSpec* spec = findCallSpec(call.keyword);
    std::size_t count = call.values.size();
    if (spec && spec->hasText && count < spec->params.size()) count = spec->params.size();
    std::string out = call.keyword + " (";
    for (std::size_t i = 0; i < count; ++i) {
        if (i) out += ", ";
        if (i < call.values.size() && call.values[i]) out += formatValue(*call.values[i]);
    }
    if (spec && spec->hasText) out += ", \"" + call.text + "\"";
    return out + ")";
}

std::string writeGne(const GneDocument& document) {
    std::string out;
    for (const GneItem& item : document.items)
        out += item.isContour ? writeContour(item.contour) : writeCall(item.call) + "\n";
    return out;
}

}  // namespace mtc::core::gne
