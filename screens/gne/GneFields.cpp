#include "screens/gne/GneFields.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <QtGlobal>  // QT_TRANSLATE_NOOP only: the texts stay plain English strings

#include "cnc_core/contour/GneSchema.h"
#include "cnc_core/contour/GneText.h"
#include "cnc_core/text/Numbers.h"

namespace mtc::screens::gnefields {

namespace gne = mtc::core::gne;
using gne::ElementKind;

namespace {

constexpr double kCoordinateLimit = 99999.999;

/// The values an element can carry.
enum class Slot {
    End0,
    End1,
    Centre0,
    Centre1,
    Angle,
    Length,
    Radius,
    Width,
    Depth,
    FaceDepth,
    Form,
    Tangent,
    Alternative
};

struct SlotSpec {
    Slot slot;
    const char* meaning;
    double minimum;
    double maximum;
    bool integer;
};

std::vector<SlotSpec> slotsOf(ElementKind kind) {
    const double c = kCoordinateLimit;
    const SlotSpec end0{Slot::End0, QT_TRANSLATE_NOOP("GneModel", "end point, 1st axis"), -c, c,
                        false};
    const SlotSpec end1{Slot::End1, QT_TRANSLATE_NOOP("GneModel", "end point, 2nd axis"), -c, c,
                        false};
    const SlotSpec tan{Slot::Tangent,
                       QT_TRANSLATE_NOOP("GneModel", "1 = tangential to the previous element"), 0,
                       1, true};
    const SlotSpec alt{Slot::Alternative,
                       QT_TRANSLATE_NOOP("GneModel", "chosen solution (0 = first)"), 0, 9, true};
    switch (kind) {
        case ElementKind::Start:
            return {
                {Slot::End0, QT_TRANSLATE_NOOP("GneModel", "start point, 1st axis"), -c, c, false},
                {Slot::End1, QT_TRANSLATE_NOOP("GneModel", "start point, 2nd axis"), -c, c, false}};
        case ElementKind::Line:
            return {end0,
                    end1,
                    {Slot::Angle,
                     QT_TRANSLATE_NOOP("GneModel", "direction in degrees from the 1st axis"), -360,
                     360, false},
                    {Slot::Length, QT_TRANSLATE_NOOP("GneModel", "length of the line"), 0.001, c,
                     false},
                    tan,
                    alt};
        case ElementKind::ArcCW:
        case ElementKind::ArcCCW:
            return {
                end0,
                end1,
                {Slot::Centre0, QT_TRANSLATE_NOOP("GneModel", "centre, 1st axis (absolute)"), -c, c,
                 false},
                {Slot::Centre1, QT_TRANSLATE_NOOP("GneModel", "centre, 2nd axis (absolute)"), -c, c,
                 false},
                {Slot::Radius, QT_TRANSLATE_NOOP("GneModel", "radius of the arc"), 0.001, c, false},
                tan,
                alt};
        case ElementKind::Round:
            return {{Slot::Radius, QT_TRANSLATE_NOOP("GneModel", "radius of the rounding"), 0.001,
                     c, false}};
        case ElementKind::Chamfer:
            return {{Slot::Width, QT_TRANSLATE_NOOP("GneModel", "width of the chamfer"), 0.001, c,
                     false}};
        case ElementKind::Relief:
            return {
                {Slot::Form, QT_TRANSLATE_NOOP("GneModel", "DIN 509 form: E or F"), 0, 0, false},
                {Slot::Radius, QT_TRANSLATE_NOOP("GneModel", "radius (empty = DIN 509 table)"),
                 0.001, 50, false},
                {Slot::Depth, QT_TRANSLATE_NOOP("GneModel", "depth into the cylinder t1"), 0.001,
                 50, false},
                {Slot::Width, QT_TRANSLATE_NOOP("GneModel", "width (empty = DIN 509 table)"), 0.001,
                 100, false},
                {Slot::FaceDepth, QT_TRANSLATE_NOOP("GneModel", "form F: depth into the face t2"),
                 0.001, 50, false}};
    }
    return {};
}

std::optional<double>* numberSlot(gne::ContourElement& e, Slot slot) {
    switch (slot) {
        case Slot::End0:
            return &e.end[0];
        case Slot::End1:
            return &e.end[1];
        case Slot::Centre0:
            return &e.centre[0];
        case Slot::Centre1:
            return &e.centre[1];
        case Slot::Angle:
            return &e.angle;
        case Slot::Length:
            return &e.length;
        case Slot::Radius:
            return &e.radius;
        case Slot::Width:
            return &e.width;
        case Slot::Depth:
            return &e.depth;
        case Slot::FaceDepth:
            return &e.faceDepth;
        default:
            return nullptr;
    }
}

std::string slotName(Slot slot, gne::GnePlane plane) {
    const char* ends = gne::endLetters(plane);
    const char* centres = gne::centreLetters(plane);
    switch (slot) {
        case Slot::End0:
            return std::string(1, ends[0]);
        case Slot::End1:
            return std::string(1, ends[1]);
        case Slot::Centre0:
            return std::string(1, centres[0]);
        case Slot::Centre1:
            return std::string(1, centres[1]);
        case Slot::Angle:
            return "A";
        case Slot::Length:
            return "L";
        case Slot::Radius:
            return "R";
        case Slot::Width:
            return "W";
        case Slot::Depth:
            return "T";
        case Slot::FaceDepth:
            return "U";
        case Slot::Form:
            return "FORM";
        case Slot::Tangent:
            return "TAN";
        case Slot::Alternative:
            return "ALT";
    }
    return "?";
}

std::string text(const std::optional<double>& value) {
    return value ? gne::formatValue(*value) : std::string();
}

std::string trimmed(const std::string& s) {
    std::size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
    return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

/// Checks `text` against a range; sets `value` (nullopt for "") or `message`.
bool checked(const std::string& name, const std::string& text, double minimum, double maximum,
             bool integer, bool required, std::optional<double>& value, ModelText& message) {
    if (text.empty()) {
        if (required) {
            message = {QT_TRANSLATE_NOOP("GneModel", "%1 must be given"), {name}};
            return false;
        }
        value.reset();
        return true;
    }
    double v = 0;
    if (!parseNumber(text, v)) {
        message = {QT_TRANSLATE_NOOP("GneModel", "%1: '%2' is not a number"), {name, text}};
        return false;
    }
    if (v < minimum || v > maximum) {
        message = {QT_TRANSLATE_NOOP("GneModel", "%1 = %2 is outside %3 .. %4"),
                   {name, text, core::formatGeneral(minimum), core::formatGeneral(maximum)}};
        return false;
    }
    if (integer && std::floor(v) != v) {
        message = {QT_TRANSLATE_NOOP("GneModel", "%1 must be a whole number"), {name}};
        return false;
    }
    value = v;
    return true;
}

}  // namespace

bool parseNumber(const std::string& raw, double& value) {
    const std::string t = trimmed(raw);
    if (t.empty() || t.size() > 30) return false;
    for (char c : t)
        if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+'))
            return false;
    return core::readNumberPrefix(t, value) == t.size() && std::isfinite(value);
}

std::vector<Field> elementFields(const gne::ContourElement& e, gne::GnePlane plane) {
    std::vector<Field> fields;
    gne::ContourElement copy = e;
    for (const SlotSpec& s : slotsOf(e.kind)) {
        Field f{slotName(s.slot, plane), s.meaning, "", false, ""};
        if (s.slot == Slot::Form)
            f.value = std::string(1, e.reliefForm), f.required = true;
        else if (s.slot == Slot::Tangent)
            f.value = e.tangent ? "1" : "0";
        else if (s.slot == Slot::Alternative)
            f.value = std::to_string(e.alternative);
        else
            f.value = text(*numberSlot(copy, s.slot));
        if (e.kind == ElementKind::Round || e.kind == ElementKind::Chamfer) f.required = true;
        fields.push_back(std::move(f));
    }
    return fields;
}

bool setElementField(gne::ContourElement& e, gne::GnePlane plane, int index, const std::string& raw,
                     ModelText& message) {
    const std::vector<SlotSpec> slots = slotsOf(e.kind);
    if (index < 0 || index >= static_cast<int>(slots.size())) {
        message = {QT_TRANSLATE_NOOP("GneModel", "no such value")};
        return false;
    }
    const SlotSpec& s = slots[static_cast<std::size_t>(index)];
    const std::string name = slotName(s.slot, plane);
    std::string t = trimmed(raw);
    if (s.slot == Slot::Form) {
        const char form = t.size() == 1 ? static_cast<char>(std::toupper(t[0])) : '?';
        if (form != 'E' && form != 'F') {
            message = {QT_TRANSLATE_NOOP("GneModel", "FORM: write E or F (DIN 509)")};
            return false;
        }
        e.reliefForm = form;
        return true;
    }
    const bool flagOrChoice = s.slot == Slot::Tangent || s.slot == Slot::Alternative;
    const bool required =
        flagOrChoice || e.kind == ElementKind::Round || e.kind == ElementKind::Chamfer;
    std::optional<double> value;
    if (!checked(name, t, s.minimum, s.maximum, s.integer, required, value, message)) return false;
    if (s.slot == Slot::Tangent)
        e.tangent = *value != 0.0;
    else if (s.slot == Slot::Alternative)
        e.alternative = static_cast<int>(*value);
    else
        *numberSlot(e, s.slot) = value;
    return true;
}

std::vector<Field> contourFields(const gne::Contour& c) {
    return {
        {"NR",
         QT_TRANSLATE_NOOP("GneModel", "contour number (the cycles machine it by this number)"),
         std::to_string(c.number), true, ""},
        {"RAW", QT_TRANSLATE_NOOP("GneModel", "0 = final part contour, 1 = raw (blank) contour"),
         c.raw ? "1" : "0", true, ""}};
}

bool setContourField(gne::Contour& c, int index, const std::string& raw, ModelText& message) {
    std::optional<double> value;
    if (index == 0) {
        if (!checked("NR", trimmed(raw), 1, 9999, true, true, value, message)) return false;
        c.number = static_cast<int>(*value);
        return true;
    }
    if (index == 1) {
        if (!checked("RAW", trimmed(raw), 0, 1, true, true, value, message)) return false;
        c.raw = *value != 0.0;
        return true;
    }
    message = {QT_TRANSLATE_NOOP("GneModel", "no such value")};
    return false;
}

std::vector<Field> callFields(const gne::GneCall& call) {
    std::vector<Field> fields;
    const gne::CallSpec* spec = gne::findCallSpec(call.keyword);
    if (!spec) return fields;
    for (std::size_t i = 0; i < spec->params.size(); ++i) {
        const gne::ParamSpec& p = spec->params[i];
        fields.push_back({p.name, p.meaning, i < call.values.size() ? text(call.values[i]) : "",
                          p.required, p.required ? "" : gne::formatValue(p.defaultValue)});
    }
    if (spec->hasText)
        fields.push_back(
            {"TEXT", QT_TRANSLATE_NOOP("GneModel", "the text to engrave"), call.text, true, ""});
    return fields;
}

bool setCallField(gne::GneCall& call, int index, const std::string& raw, ModelText& message) {
    const gne::CallSpec* spec = gne::findCallSpec(call.keyword);
    const int count = spec ? static_cast<int>(spec->params.size()) : 0;
    if (spec && spec->hasText && index == count) {
        const std::string t = trimmed(raw);
        if (t.empty() || t.find('"') != std::string::npos || t.size() > 40) {
            message = {QT_TRANSLATE_NOOP("GneModel", "TEXT: 1 to 40 characters without '\"'")};
            return false;
        }
        call.text = t;
        return true;
    }
    if (!spec || index < 0 || index >= count) {
        message = {QT_TRANSLATE_NOOP("GneModel", "no such value")};
        return false;
    }
    const gne::ParamSpec& p = spec->params[static_cast<std::size_t>(index)];
    std::optional<double> value;
    if (!checked(p.name, trimmed(raw), p.minimum, p.maximum, p.integer, p.required, value, message))
        return false;
    if (call.values.size() <= static_cast<std::size_t>(index))
        call.values.resize(static_cast<std::size_t>(index) + 1);
    call.values[static_cast<std::size_t>(index)] = value;
    return true;
}

gne::GneCall newCall(const std::string& keyword, int number) {
    struct Start {
        const char* keyword;
        std::vector<double> values;
        const char* text;
    };
    // Usable first values for every required parameter (NR is replaced).
    static const std::vector<Start> starts = {
        {"WINDOW_01", {-80, 2, 30, 0}, ""},
        {"WINDOW_02", {-10, -10, 110, 70}, ""},
        {"FORM_20", {0, -20, 20, 4, 2}, ""},
        {"FORM_50", {0, 20, 20, 60, 20, 10}, ""},
        {"FORM_51", {0, 50, 30, 20, 0, 90, 8}, ""},
        {"FORM_52", {0, 50, 30, 12}, ""},
        {"FORM_53", {0, 50, 30, 15, 6}, ""},
        {"FORM_54", {0, 10, 10, 8}, "MTC"},
        {"FORM_55", {0, 50, 30, 20, 90, 6}, "MTC"},
        {"FORM_56", {0, 10, 10, 90, 50}, ""},
        {"FORM_57", {0, 50, 30, 60, 30}, ""},
        {"CYCLE_10", {0, 1, 0.15}, ""},
        {"CYCLE_11", {0, 1, 0.3, 0, 3, 0.8, 80, 95, 1, 2}, ""},
        {"CYCLE_12", {0, 1, 0.2}, ""},
        {"CYCLE_40", {0, 1, 300, 0, 5, 1, 2, -2}, ""},
    };
    gne::GneCall call;
    call.keyword = keyword;
    for (const Start& s : starts) {
        if (keyword != s.keyword) continue;
        for (double v : s.values)
            call.values.emplace_back(v);
        call.text = s.text;
    }
    if (keyword.rfind("WINDOW_", 0) != 0 && !call.values.empty()) call.values[0] = number;
    return call;
}

}  // namespace mtc::screens::gnefields
