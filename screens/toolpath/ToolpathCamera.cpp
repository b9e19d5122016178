#include "screens/toolpath/ToolpathCamera.h"

#include <cmath>

namespace mtc::screens {

namespace {
using Vec = std::array<double, 3>;

Vec cross(const Vec& a, const Vec& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Vec normalised(const Vec& v) {
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return n > 0 ? Vec{v[0] / n, v[1] / n, v[2] / n} : v;
}

/// Rodrigues: v turned by `degrees` about unit axis k.
Vec turned(const Vec& v, const Vec& k, double degrees) {
    const double a = degrees * 3.14159265358979323846 / 180.0, c = std::cos(a), s = std::sin(a);
    const Vec kv = cross(k, v);
    const double kd = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
    Vec out;
    for (int i = 0; i < 3; ++i) {
        const auto j = static_cast<std::size_t>(i);
        out[j] = v[j] * c + kv[j] * s + k[j] * kd * (1 - c);
    }
    return out;
}
}  // namespace

std::array<double, 3> CameraPose::right() const {
    return cross(direction, up);
}

void CameraPose::rotate(double azimuth, double elevation) {
    direction = normalised(turned(direction, up, azimuth));
    const Vec axis = normalised(right());
    direction = normalised(turned(direction, axis, elevation));
    up = normalised(turned(up, axis, elevation));
}

CameraPose presetPose(ToolpathPreset preset) {
    switch (preset) {
        case ToolpathPreset::G17:
            return {{0, 0, -1}, {0, 1, 0}};
        case ToolpathPreset::G18:
            return {{0, -1, 0}, {1, 0, 0}};
        case ToolpathPreset::G19:
            return {{-1, 0, 0}, {0, 0, 1}};
        case ToolpathPreset::Isometric:
            break;
    }
    const double s = 1.0 / std::sqrt(3.0), u = 1.0 / std::sqrt(6.0);
    return {{-s, s, -s}, {-u, u, 2 * u}};  // seen from (1, -1, 1), Z up
}

const char* presetName(ToolpathPreset preset) {
    switch (preset) {
        case ToolpathPreset::G17:
            return "G17 (XY)";
        case ToolpathPreset::G18:
            return "G18 (ZX)";
        case ToolpathPreset::G19:
            return "G19 (YZ)";
        case ToolpathPreset::Isometric:
            break;
    }
    return "isometric";
}

}  // namespace mtc::screens
