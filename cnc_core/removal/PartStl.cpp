#include "cnc_core/removal/PartStl.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "cnc_core/program/AtomicWrite.h"
#include "cnc_core/toolpath/CurveMath.h"

namespace mtc::core::removal {

namespace {

using Point = std::array<double, 3>;

/// Vertex positions along one grid direction: the cell centres, the first
/// and last moved out onto the stock's faces (two when there is one cell).
struct VertexLine {
    std::vector<double> position;
    std::vector<int> cell;  ///< the cell whose value a vertex takes
};

VertexLine vertexLine(int cells, double min, double max, double size) {
    VertexLine line;
    const int count = std::max(cells, 2);
    for (int k = 0; k < count; ++k) {
        const int cell = std::min(k, cells - 1);
        line.cell.push_back(cell);
        line.position.push_back(k == 0 ? min : k == count - 1 ? max : min + (cell + 0.5) * size);
    }
    return line;
}

/// Appends binary STL triangles to a string.
class StlBuffer {
  public:
    explicit StlBuffer(std::uint64_t triangles) {
        data_.reserve(84 + 50 * triangles);
        data_.append(80, '\0');
        std::memcpy(data_.data(), "mtc200 simulate: finished part (mm)", 35);
        putUint32(static_cast<std::uint32_t>(triangles));
    }
    void triangle(const Point& a, const Point& b, const Point& c) {
        const Point u{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const Point v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        Point n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (double& x : n)
            x = length > 0.0 ? x / length : 0.0;
        const Point n0 = n;
        for (const Point* p : {&n0, &a, &b, &c})
            for (double x : *p)
                putFloat(static_cast<float>(x));
        data_.append(2, '\0');
    }
    /// Two triangles; p0..p3 counter-clockwise seen from outside.
    void quad(const Point& p0, const Point& p1, const Point& p2, const Point& p3) {
        triangle(p0, p1, p2);
        triangle(p0, p2, p3);
    }
    std::string take() { return std::move(data_); }

  private:
    void putUint32(std::uint32_t v) {
        for (int i = 0; i < 4; ++i)
            data_.push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
    }
    void putFloat(float f) {
        std::uint32_t bits = 0;
        std::memcpy(&bits, &f, sizeof bits);
        putUint32(bits);  // little-endian whatever the host
    }
    std::string data_;
};

/// Keeps the triangles' corners as floats (the view's mesh).
class TriangleBuffer {
  public:
    explicit TriangleBuffer(std::uint64_t triangles) { data_.reserve(9 * triangles); }
    void triangle(const Point& a, const Point& b, const Point& c) {
        for (const Point* p : {&a, &b, &c})
            for (double x : *p)
                data_.push_back(static_cast<float>(x));
    }
    /// Two triangles; p0..p3 counter-clockwise seen from outside.
    void quad(const Point& p0, const Point& p1, const Point& p2, const Point& p3) {
        triangle(p0, p1, p2);
        triangle(p0, p2, p3);
    }
    std::vector<float> take() { return std::move(data_); }

  private:
    std::vector<float> data_;
};

/// Whether the view's mesh merges runs of facets that lie in one plane
/// (partTriangles) or keeps one quad per cell as the STL does.
enum class Facets { PerCell, MergeRuns };

/// Where the runs of one strip of facets begin and end: vertex indices
/// along the strip, ascending, the first 0 and the last its end.
using RunBounds = std::vector<int>;

RunBounds everyVertex(int count) {
    RunBounds all(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i)
        all[static_cast<std::size_t>(i)] = i;
    return all;
}

/// A run of facets in one plane from vertex a to vertex b of its strip,
/// as triangles through every vertex the neighbouring strips' runs have on
/// its two edges (`low`, `high`): no vertex lies inside another triangle's
/// edge, so a rasteriser leaves no cracks between the runs (a T-junction
/// would). `corner(i, high)` is vertex i of the low or the high edge; the
/// low edge runs a -> b counter-clockwise seen from outside.
template <typename Out, typename Corner>
void zipRun(Out& out, int a, int b, const RunBounds& low, const RunBounds& high, Corner corner) {
    const auto onEdge = [a, b](const RunBounds& neighbour) {
        RunBounds v{a};
        for (int i : neighbour)
            if (i > a && i < b) v.push_back(i);
        v.push_back(b);
        return v;
    };
    const RunBounds l = onEdge(low), h = onEdge(high);
    std::size_t i = 0, j = 0;
    while (i + 1 < l.size() || j + 1 < h.size()) {
        if (j + 1 == h.size() || (i + 1 < l.size() && l[i + 1] <= h[j + 1])) {
            out.triangle(corner(l[i], false), corner(l[i + 1], false), corner(h[j], true));
            ++i;
        } else {
            out.triangle(corner(l[i], false), corner(h[j + 1], true), corner(h[j], true));
            ++j;
        }
    }
}

template <typename Out>
void heightFieldSurface(const HeightField& f, Out& out, Facets facets = Facets::PerCell) {
    const Box& box = f.stock();
    const VertexLine xs = vertexLine(f.columns(), box.min[0], box.max[0], f.cellWidth());
    const VertexLine ys = vertexLine(f.rows(), box.min[1], box.max[1], f.cellDepth());
    const int nu = static_cast<int>(xs.position.size()), nv = static_cast<int>(ys.position.size());
    const double zb = box.min[2];
    const auto top = [&](int k, int l) {
        return Point{xs.position[k], ys.position[l], f.height(xs.cell[k], ys.cell[l])};
    };
    const auto bottom = [&](int k, int l) { return Point{xs.position[k], ys.position[l], zb}; };
    // A quad whose four corners have one height is flat; a run of flat
    // quads of one height along a row is one piece of the same surface.
    std::vector<RunBounds> runs(static_cast<std::size_t>(nv - 1));
    for (int l = 0; l + 1 < nv; ++l) {
        const auto flatAt = [&](int k, double z) {
            return f.height(xs.cell[k], ys.cell[l]) == z &&
                   f.height(xs.cell[k + 1], ys.cell[l]) == z &&
                   f.height(xs.cell[k], ys.cell[l + 1]) == z &&
                   f.height(xs.cell[k + 1], ys.cell[l + 1]) == z;
        };
        RunBounds& row = runs[static_cast<std::size_t>(l)];
        for (int k = 0; k + 1 < nu;) {
            row.push_back(k);
            int end = k + 1;
            const double z = f.height(xs.cell[k], ys.cell[l]);
            if (facets == Facets::MergeRuns && flatAt(k, z))
                while (end + 1 < nu && flatAt(end, z))
                    ++end;
            k = end;
        }
        row.push_back(nu - 1);
    }
    const RunBounds border = everyVertex(nu);  // the side walls have every vertex
    for (int l = 0; l + 1 < nv; ++l) {
        const RunBounds& row = runs[static_cast<std::size_t>(l)];
        const RunBounds& below = l == 0 ? border : runs[static_cast<std::size_t>(l - 1)];
        const RunBounds& above = l + 2 == nv ? border : runs[static_cast<std::size_t>(l) + 1];
        for (std::size_t r = 0; r + 1 < row.size(); ++r) {
            const int k = row[r], end = row[r + 1];
            if (end == k + 1)  // one cell: as the STL splits it
                out.quad(top(k, l), top(k + 1, l), top(k + 1, l + 1), top(k, l + 1));
            else
                zipRun(out, k, end, below, above,
                       [&](int i, bool high) { return top(i, high ? l + 1 : l); });
        }
    }
    for (int k = 0; k + 1 < nu; ++k) {
        out.quad(bottom(k, 0), bottom(k + 1, 0), top(k + 1, 0), top(k, 0));  // -Y
        out.quad(bottom(k + 1, nv - 1), bottom(k, nv - 1), top(k, nv - 1), top(k + 1, nv - 1));
    }
    for (int l = 0; l + 1 < nv; ++l) {
        out.quad(bottom(0, l + 1), bottom(0, l), top(0, l), top(0, l + 1));  // -X
        out.quad(bottom(nu - 1, l), bottom(nu - 1, l + 1), top(nu - 1, l + 1), top(nu - 1, l));
    }
    // Bottom: a fan around its centre over the border vertices the walls use.
    const Point centre{(box.min[0] + box.max[0]) / 2, (box.min[1] + box.max[1]) / 2, zb};
    for (int k = 0; k + 1 < nu; ++k) {
        out.triangle(centre, bottom(k + 1, 0), bottom(k, 0));
        out.triangle(centre, bottom(k, nv - 1), bottom(k + 1, nv - 1));
    }
    for (int l = 0; l + 1 < nv; ++l) {
        out.triangle(centre, bottom(0, l), bottom(0, l + 1));
        out.triangle(centre, bottom(nu - 1, l + 1), bottom(nu - 1, l));
    }
}

/// Facets around the axis of a turned part: the jacket's columns when G32
/// cut it (D-027), else angularSegments().
int turnedSegments(const PartModel& part) {
    return part.jacket() != nullptr ? part.jacket()->columns() : part.angularSegments();
}

template <typename Out>
void turnedSurface(const PartModel& part, Out& out, Facets facets = Facets::PerCell) {
    const TurnedProfile& p = *part.profile();
    const DevelopedSurface* jacket = part.jacket();
    const VertexLine zs = vertexLine(p.slices(), p.from(), p.to(), p.sliceLength());
    const int rings = static_cast<int>(zs.position.size()), segments = turnedSegments(part);
    const auto axial = static_cast<std::size_t>(part.axialAxis());
    const auto radial = static_cast<std::size_t>(part.radialAxis());
    const auto third = static_cast<std::size_t>((part.axialAxis() + 2) % 3);
    // Revolved: a ring of `segments` facets per vertex line; with a jacket
    // the vertices stand on its cell centres at the material's radius there.
    const auto radius = [&](int k, int s) {
        const int cell = zs.cell[static_cast<std::size_t>(k)];
        const double r = p.radiusAt(cell);
        return jacket != nullptr ? std::min(r, jacket->radius(s % segments, cell)) : r;
    };
    const auto point = [&](int k, int s) {
        const double angle = jacket != nullptr ? jacket->columnAngle(s % segments)
                                               : 2.0 * curve::kPi * (s % segments) / segments;
        const double r = radius(k, s);
        Point q{0, 0, 0};
        q[axial] = zs.position[static_cast<std::size_t>(k)];
        q[radial] = r * std::cos(angle);
        q[third] = r * std::sin(angle);
        return q;
    };
    const auto axisPoint = [&](int k) {
        Point q{0, 0, 0};
        q[axial] = zs.position[static_cast<std::size_t>(k)];
        return q;
    };
    if (facets == Facets::PerCell) {
        for (int k = 0; k + 1 < rings; ++k)
            for (int s = 0; s < segments; ++s)
                out.quad(point(k, s), point(k, s + 1), point(k + 1, s + 1), point(k + 1, s));
    } else {
        // Along the axis: a run of facets whose edges keep their radii is
        // one piece of the same surface (a turned diameter, its length).
        std::vector<RunBounds> runs(static_cast<std::size_t>(segments));
        for (int s = 0; s < segments; ++s) {
            const auto straight = [&](int k, double r0, double r1) {
                return radius(k, s) == r0 && radius(k + 1, s) == r0 && radius(k, s + 1) == r1 &&
                       radius(k + 1, s + 1) == r1;
            };
            RunBounds& facet = runs[static_cast<std::size_t>(s)];
            for (int k = 0; k + 1 < rings;) {
                facet.push_back(k);
                const double r0 = radius(k, s), r1 = radius(k, s + 1);
                int end = k + 1;
                if (straight(k, r0, r1))
                    while (end + 1 < rings && straight(end, r0, r1))
                        ++end;
                k = end;
            }
            facet.push_back(rings - 1);
        }
        for (int s = 0; s < segments; ++s) {
            const RunBounds& facet = runs[static_cast<std::size_t>(s)];
            // The edge at angle s + 1 is shared with facet s + 1, the one at s
            // with facet s - 1.
            const RunBounds& next = runs[static_cast<std::size_t>((s + 1) % segments)];
            const RunBounds& previous =
                runs[static_cast<std::size_t>((s + segments - 1) % segments)];
            for (std::size_t r = 0; r + 1 < facet.size(); ++r) {
                const int k = facet[r], end = facet[r + 1];
                if (end == k + 1)
                    out.quad(point(k, s), point(k, s + 1), point(k + 1, s + 1), point(k + 1, s));
                else
                    zipRun(out, k, end, next, previous,
                           [&](int i, bool high) { return point(i, high ? s : s + 1); });
            }
        }
    }
    for (int s = 0; s < segments; ++s) {
        out.triangle(axisPoint(0), point(0, s + 1), point(0, s));
        out.triangle(axisPoint(rings - 1), point(rings - 1, s), point(rings - 1, s + 1));
    }
}

}  // namespace

std::uint64_t stlTriangleCount(const PartModel& part) {
    if (const HeightField* f = part.heightField()) {
        const std::uint64_t nu = std::max(f->columns(), 2), nv = std::max(f->rows(), 2);
        return 2 * (nu - 1) * (nv - 1) + 6 * (nu - 1) + 6 * (nv - 1);
    }
    const std::uint64_t rings = std::max(part.profile()->slices(), 2);
    const std::uint64_t segments = static_cast<std::uint64_t>(turnedSegments(part));
    return 2 * (rings - 1) * segments + 2 * segments;
}

std::string partStl(const PartModel& part) {
    StlBuffer out(stlTriangleCount(part));
    if (const HeightField* f = part.heightField())
        heightFieldSurface(*f, out);
    else
        turnedSurface(part, out);
    return out.take();
}

std::vector<float> partTriangles(const PartModel& part) {
    TriangleBuffer out(0);
    if (const HeightField* f = part.heightField())
        heightFieldSurface(*f, out, Facets::MergeRuns);
    else
        turnedSurface(part, out, Facets::MergeRuns);
    return out.take();
}

bool writePartStl(const PartModel& part, const std::string& path, std::string& error) {
    return writeFileAtomically(path, partStl(part), error);
}

}  // namespace mtc::core::removal
