#include "screens/toolpath/ToolpathPartRaster.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mtc::screens {

namespace {

using Vec = std::array<double, 3>;

double dot(const Vec& a, const Vec& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// A corner on the image: x, y in device pixels, depth towards the viewer.
struct Corner {
    double x, y, depth;
};

/// Fills the pixels whose centres lie in the triangle (either winding) and
/// are nearer than what the depth buffer holds.
class Filler {
  public:
    Filler(QImage& image, std::vector<float>& depth) : image_(image), depth_(depth) {}

    void fill(const Corner& a, const Corner& b, const Corner& c, QRgb rgb) {
        const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        if (!(std::fabs(area) > 1e-12)) return;  // edge-on (or NaN)
        const int w = image_.width(), h = image_.height();
        const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x, b.x, c.x}))));
        const int x1 = std::min(w - 1, static_cast<int>(std::ceil(std::max({a.x, b.x, c.x}))));
        const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y, b.y, c.y}))));
        const int y1 = std::min(h - 1, static_cast<int>(std::ceil(std::max({a.y, b.y, c.y}))));
        const double inverse = 1.0 / area;
        for (int y = y0; y <= y1; ++y) {
            auto* line = reinterpret_cast<QRgb*>(image_.scanLine(y));
            float* nearest =
                depth_.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(w);
            const double py = y + 0.5;
            for (int x = x0; x <= x1; ++x) {
                const double px = x + 0.5;
                // Barycentric weights; all of one sign inside (either winding).
                const double wa = ((b.x - px) * (c.y - py) - (b.y - py) * (c.x - px)) * inverse;
                const double wb = ((c.x - px) * (a.y - py) - (c.y - py) * (a.x - px)) * inverse;
                const double wc = 1.0 - wa - wb;
                if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
                const auto z = static_cast<float>(wa * a.depth + wb * b.depth + wc * c.depth);
                if (z <= nearest[x]) continue;
                nearest[x] = z;
                line[x] = rgb;
            }
        }
    }

  private:
    QImage& image_;
    std::vector<float>& depth_;
};

}  // namespace

QImage rasterizePart(const std::vector<float>& triangles, const QColor& colour, bool shadeByHeight,
                     const PartProjection& view, QSize size) {
    QImage image(size.expandedTo(QSize(1, 1)), QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    const std::size_t count = triangles.size() / 9;
    if (count == 0 || size.isEmpty()) return image;
    std::vector<float> depth(
        static_cast<std::size_t>(image.width()) * static_cast<std::size_t>(image.height()),
        -std::numeric_limits<float>::infinity());
    float zMin = triangles[2], zMax = triangles[2];
    for (std::size_t i = 2; i < triangles.size(); i += 3) {
        zMin = std::min(zMin, triangles[i]);
        zMax = std::max(zMax, triangles[i]);
    }
    const double span = zMax > zMin ? zMax - zMin : 1.0;
    const auto corner = [&](const float* p) {
        const Vec d{p[0] - view.focal[0], p[1] - view.focal[1], p[2] - view.focal[2]};
        return Corner{view.centreX + view.scale * dot(d, view.right),
                      view.centreY - view.scale * dot(d, view.up), dot(d, view.toward)};
    };
    Filler filler(image, depth);
    for (std::size_t t = 0; t < count; ++t) {
        const float* p = &triangles[9 * t];
        const Vec u{p[3] - p[0], p[4] - p[1], p[5] - p[2]};
        const Vec v{p[6] - p[0], p[7] - p[1], p[8] - p[2]};
        const Vec n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                    u[0] * v[1] - u[1] * v[0]};
        const double length = std::sqrt(dot(n, n));
        const double facing = length > 0.0 ? std::fabs(dot(n, view.toward)) / length : 0.0;
        double shade = 0.35 + 0.65 * facing;  // the 3D view's ambient and diffuse
        if (shadeByHeight)  // the corners' mean height, as the 3D view colours them
            shade *= 0.45 + 0.55 * ((p[2] + p[5] + p[8]) / 3.0 - zMin) / span;
        const auto channel = [shade](int c) {
            return std::clamp(static_cast<int>(std::lround(c * shade)), 0, 255);
        };
        const QRgb rgb =
            qRgb(channel(colour.red()), channel(colour.green()), channel(colour.blue()));
        filler.fill(corner(p), corner(p + 3), corner(p + 6), rgb);
    }
    return image;
}

}  // namespace mtc::screens
