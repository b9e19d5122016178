#include "cnc_core/contour/GneSchema.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "cnc_core/text/Numbers.h"

namespace mtc::core::gne {
namespace {

constexpr double kBig = kMaxGneValue;

ParamSpec req(const char* name, const char* meaning, double lo = -kBig, double hi = kBig) {
    return {name, meaning, true, 0.0, lo, hi, false};
}
ParamSpec opt(const char* name, const char* meaning, double def, double lo = -kBig,
              double hi = kBig) {
    return {name, meaning, false, def, lo, hi, false};
}
ParamSpec number(const char* meaning) {
    return {"NR", meaning, true, 0.0, 1, 9999, true};
}

std::vector<ParamSpec> turningCycle(std::vector<ParamSpec> extra) {
    std::vector<ParamSpec> p = {
        number("number of the contour or form to machine"),
        {"T", "tool number", true, 0, 1, 999, true},
        req("F", "feed (mm/rev or mm/min as programmed)", 0.001, 100000),
        opt("S", "spindle speed, 0 = leave unchanged", 0, 0, 100000),
        {"EDGE", "cutting edge orientation assumed (0..9)", false, 3, 0, 9, true},
        opt("TR", "tool nose radius assumed", 0, 0, 50),
        opt("CA", "corner angle of the insert assumed (degrees)", 80, 1, 180),
        opt("SA", "setting angle of the tool assumed (degrees)", 95, 0, 180),
        opt("SC", "safety clearance for approach and retract", 1, 0.01, 100),
    };
    p.insert(p.end(), extra.begin(), extra.end());
    return p;
}

std::vector<CallSpec> buildSpecs() {
    const GnePlane T = GnePlane::Turning, M = GnePlane::Milling;
    return {
        {"WINDOW_01",
         "drawing window and blank - turning",
         T,
         false,
         {req("ZMIN", "left end of the blank"), req("ZMAX", "right end of the blank"),
          req("XMAX", "outer radius of the blank", 0.001), opt("XMIN", "bore radius", 0, 0)}},
        {"WINDOW_02",
         "drawing window and blank - milling",
         M,
         false,
         {req("XMIN", "blank corner X"), req("YMIN", "blank corner Y"),
          req("XMAX", "opposite corner X"), req("YMAX", "opposite corner Y"),
          opt("ZTOP", "top face of the blank", 0), opt("ZBOT", "bottom face of the blank", -10)}},
        {"FORM_20",
         "recess - turning",
         T,
         false,
         {number("geometry number"), req("Z", "right flank of the recess"),
          req("X", "radius the recess starts from", 0.001), req("W", "width of the recess", 0.001),
          req("D", "depth of the recess", 0.001)}},
        {"FORM_50",
         "straight elongated hole - milling",
         M,
         false,
         {number("geometry number"), req("X1", "centre of the 1st end"),
          req("Y1", "centre of the 1st end"), req("X2", "centre of the 2nd end"),
          req("Y2", "centre of the 2nd end"), req("W", "width of the hole", 0.001)}},
        {"FORM_51",
         "round elongated hole - milling",
         M,
         false,
         {number("geometry number"), req("XC", "centre of the arc"), req("YC", "centre of the arc"),
          req("R", "radius of the middle line", 0.001), req("A1", "start angle (degrees)"),
          req("A2", "end angle (degrees, counter-clockwise from A1)"),
          req("W", "width of the hole", 0.001)}},
        {"FORM_52",
         "circle - milling",
         M,
         false,
         {number("geometry number"), req("XC", "centre"), req("YC", "centre"),
          req("R", "radius", 0.001)}},
        {"FORM_53",
         "polygon - milling",
         M,
         false,
         {number("geometry number"),
          req("XC", "centre"),
          req("YC", "centre"),
          req("R", "radius of the circumscribed circle", 0.001),
          {"N", "number of corners", true, 0, 3, 360, true},
          opt("A0", "angle of the first corner (degrees)", 90)}},
        {"FORM_54",
         "straight text - milling",
         M,
         true,
         {number("geometry number"), req("X", "start of the base line"),
          req("Y", "start of the base line"), req("H", "character height", 0.1),
          opt("A", "angle of the base line (degrees)", 0)}},
        {"FORM_55",
         "round text - milling",
         M,
         true,
         {number("geometry number"), req("XC", "centre of the base circle"),
          req("YC", "centre of the base circle"), req("R", "radius of the base circle", 0.1),
          opt("A0", "angle of the first character (degrees)", 90),
          req("H", "character height", 0.1)}},
        {"FORM_56",
         "rectangle - milling",
         M,
         false,
         {number("geometry number"), req("X1", "corner"), req("Y1", "corner"),
          req("X2", "opposite corner"), req("Y2", "opposite corner"),
          opt("RC", "corner radius", 0, 0)}},
        {"FORM_57",
         "rectangle centred - milling",
         M,
         false,
         {number("geometry number"), req("XC", "centre"), req("YC", "centre"),
          req("L", "length along the angle", 0.001), req("W", "width", 0.001),
          opt("A", "angle of the length side (degrees)", 0), opt("RC", "corner radius", 0, 0)}},
        {"CYCLE_10", "contour cut - turning", T, false, turningCycle({})},
        {"CYCLE_11", "roughing - turning", T, false,
         turningCycle({req("DEPTH", "depth of cut per pass (radius)", 0.01, 50),
                       opt("AX", "allowance in X (radius)", 0.5, 0, 50),
                       opt("AZ", "allowance in Z", 0.2, 0, 50)})},
        {"CYCLE_12", "residual cut - turning", T, false,
         turningCycle({opt("A", "uniform allowance left for the contour cut", 0.2, 0, 50)})},
        {"CYCLE_40",
         "contour cut - milling",
         M,
         false,
         {number("number of the contour or form to machine"),
          {"T", "tool number", true, 0, 1, 999, true},
          req("F", "feed (mm/min)", 0.001, 100000),
          opt("S", "spindle speed, 0 = leave unchanged", 0, 0, 100000),
          opt("TR", "tool radius assumed", 0, 0, 100),
          {"SIDE", "0 on the contour, 1 left (G41), 2 right (G42)", false, 1, 0, 2, true},
          req("ZS", "safety plane"),
          req("ZC", "cutting depth (absolute Z)"),
          opt("FZ", "plunge feed, 0 = F", 0, 0, 100000)}},
    };
}

}  // namespace

const std::vector<CallSpec>& callSpecs() {
    static const std::vector<CallSpec> specs = buildSpecs();
    return specs;
}

const CallSpec* findCallSpec(std::string_view keyword) {
    for (const CallSpec& spec : callSpecs())
        if (keyword == spec.keyword) return &spec;
    return nullptr;
}

std::string checkParam(const ParamSpec& spec, std::optional<double> value) {
    if (!value) return spec.required ? std::string(spec.name) + " is missing" : std::string();
    if (!std::isfinite(*value)) return std::string(spec.name) + " is not a number";
    if (*value < spec.minimum || *value > spec.maximum) {
        return std::string(spec.name) + " = " + formatGeneral(*value) + " is outside " +
               formatGeneral(spec.minimum) + " .. " + formatGeneral(spec.maximum);
    }
    if (spec.integer && std::floor(*value) != *value)
        return std::string(spec.name) + " must be a whole number";
    return {};
}

double paramValue(const CallSpec& spec, const GneCall& call, std::size_t index) {
    if (index < call.values.size() && call.values[index]) return *call.values[index];
    return index < spec.params.size() ? spec.params[index].defaultValue : 0.0;
}

}  // namespace mtc::core::gne
