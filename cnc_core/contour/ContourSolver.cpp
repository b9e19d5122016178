#include "cnc_core/contour/ContourSolver.h"

#include <cmath>
#include <optional>

#include "cnc_core/contour/GneText.h"

namespace mtc::core::gne {
namespace {

bool isPrimary(ElementKind k) {
    return k == ElementKind::Start || k == ElementKind::Line || k == ElementKind::ArcCW ||
           k == ElementKind::ArcCCW;
}
bool isArc(ElementKind k) {
    return k == ElementKind::ArcCW || k == ElementKind::ArcCCW;
}

/// The state of the chain when an element is solved.
struct ChainState {
    Point start = Point::Zero();
    std::optional<Point> direction;  ///< end tangent of the previous element
};

struct Outcome {
    ElementState state = ElementState::Solved;
    std::string message;
    std::vector<Segment> candidates;
};

Outcome fail(ElementState state, std::string message) {
    return {state, std::move(message), {}};
}

std::optional<Point> fullEnd(const ContourElement& e) {
    if (e.end[0] && e.end[1]) return Point(*e.end[0], *e.end[1]);
    return std::nullopt;
}

/// Direction of a LINE from its own data: A and/or TAN (checked against each other).
std::optional<Point> lineDirection(const ContourElement& e, const ChainState& chain,
                                   std::string& problem) {
    std::optional<Point> d;
    if (e.angle) d = direction(*e.angle);
    if (e.tangent) {
        if (!chain.direction) {
            problem = "TAN needs a preceding element with a direction";
            return std::nullopt;
        }
        if (d && (*d - *chain.direction).norm() > 1e-6) {
            problem = "A contradicts TAN";
            return std::nullopt;
        }
        d = chain.direction;
    }
    return d;
}

/// Centre candidates of an arc from its own data (centre words, TAN, R);
/// empty = not determined by the element alone.
std::vector<Point> arcCentres(const ContourElement& e, const ChainState& chain,
                              std::string& problem) {
    std::vector<Locus> loci;
    if (e.centre[0]) loci.push_back(Locus::line(Point(*e.centre[0], 0), Point::UnitY()));
    if (e.centre[1]) loci.push_back(Locus::line(Point(0, *e.centre[1]), Point::UnitX()));
    if (e.tangent) {
        if (!chain.direction) {
            problem = "TAN needs a preceding element with a direction";
            return {};
        }
        loci.push_back(Locus::line(chain.start, leftNormal(*chain.direction)));
    }
    if (e.radius) loci.push_back(Locus::around(chain.start, *e.radius));
    if (loci.size() < 2) return {};
    std::vector<Point> centres = intersect(loci[0], loci[1]);
    std::vector<Point> kept;
    for (const Point& c : centres) {
        bool fits = true;
        for (std::size_t i = 2; i < loci.size(); ++i)
            fits = fits && loci[i].contains(c);
        if (e.tangent) {
            const double side = cross(*chain.direction, c - chain.start);
            fits = fits && (e.kind == ElementKind::ArcCCW ? side > 0 : side < 0);
        }
        if (fits) kept.push_back(c);
    }
    if (kept.empty())
        problem = centres.empty() ? "the centre data have no common point"
                                  : "the centre data contradict each other";
    return kept;
}

/// Loci of the end point from the element's own data.
void ownLoci(const ContourElement& e, const ChainState& chain, const std::optional<Point>& dir,
             const std::vector<Point>& centres, std::vector<Locus>& loci) {
    if (e.end[0]) loci.push_back(Locus::line(Point(*e.end[0], 0), Point::UnitY()));
    if (e.end[1]) loci.push_back(Locus::line(Point(0, *e.end[1]), Point::UnitX()));
    if (e.kind == ElementKind::Line) {
        if (dir) loci.push_back(Locus::line(chain.start, *dir));
        if (e.length) loci.push_back(Locus::around(chain.start, *e.length));
    } else if (centres.size() == 1) {
        loci.push_back(Locus::around(centres[0], (chain.start - centres[0]).norm()));
    }
}

/// Loci of the end point that the next element gives when its own end is known.
void nextLoci(const ContourElement& e, const ContourElement* next, const std::optional<Point>& dir,
              const std::vector<Point>& centres, std::vector<Locus>& loci) {
    if (!next) return;
    const std::optional<Point> end = fullEnd(*next);
    if (!end) return;
    if (next->kind == ElementKind::Line) {
        if (next->angle) loci.push_back(Locus::line(*end, direction(*next->angle)));
        if (next->length) loci.push_back(Locus::around(*end, *next->length));
        if (next->tangent && !next->angle) {
            if (e.kind == ElementKind::Line && dir) loci.push_back(Locus::line(*end, *dir));
            if (isArc(e.kind) && centres.size() == 1)  // tangent from `end` to our circle
                loci.push_back(
                    Locus::around((centres[0] + *end) / 2, (*end - centres[0]).norm() / 2));
        }
    } else if (isArc(next->kind) && next->centre[0] && next->centre[1]) {
        const Point c(*next->centre[0], *next->centre[1]);
        loci.push_back(Locus::around(c, (*end - c).norm()));
    }
}

/// Every end point that satisfies all loci (and lies ahead on a LINE).
Outcome endPoints(const std::vector<Locus>& loci, const ContourElement& e, const ChainState& chain,
                  const std::optional<Point>& dir, std::vector<Point>& points) {
    std::size_t second = 1;
    bool same = true;
    std::vector<Point> raw;
    for (; second < loci.size() && raw.empty(); ++second) {
        raw = intersect(loci[0], loci[second], &same);
        if (!raw.empty() || !same) break;
    }
    if (raw.empty() && (second >= loci.size() || same))
        return fail(ElementState::Undetermined,
                    "too few data: give another coordinate, angle, "
                    "length or the next element's end point");
    if (raw.empty()) return fail(ElementState::Impossible, "the data have no common point");
    for (const Point& p : raw) {
        bool fits = true;
        for (std::size_t i = 1; i < loci.size(); ++i)
            if (i != second) fits = fits && loci[i].contains(p);
        if (e.kind == ElementKind::Line && dir)
            fits = fits && (p - chain.start).dot(*dir) > kTolerance;
        if (fits) points.push_back(p);
    }
    if (points.empty())
        return fail(ElementState::Overdetermined,
                    "the data contradict each other (one value too many)");
    return {};
}

/// Arc segments from start, end and the known or derived centre.
Outcome arcCandidates(const ContourElement& e, const ChainState& chain, const Point& end,
                      std::vector<Point> centres) {
    const Segment::Kind kind = e.kind == ElementKind::ArcCW ? Segment::ArcCW : Segment::ArcCCW;
    if (centres.empty() && e.tangent && chain.direction) {
        const Locus normal = Locus::line(chain.start, leftNormal(*chain.direction));
        const Locus bisector = Locus::line((chain.start + end) / 2, leftNormal(end - chain.start));
        centres = intersect(normal, bisector);
    } else if (centres.empty() && e.radius) {
        centres = intersect(Locus::around(chain.start, *e.radius), Locus::around(end, *e.radius));
    } else if (centres.empty() && (e.centre[0] || e.centre[1])) {
        const Locus bisector = Locus::line((chain.start + end) / 2, leftNormal(end - chain.start));
        const Locus given = e.centre[0] ? Locus::line(Point(*e.centre[0], 0), Point::UnitY())
                                        : Locus::line(Point(0, *e.centre[1]), Point::UnitX());
        centres = intersect(bisector, given);
    }
    if (centres.empty())
        return fail(ElementState::Undetermined, "the centre is not determined: give it, R or TAN");
    Outcome out;
    for (const Point& c : centres) {
        const double r = (chain.start - c).norm();
        if (r < kTolerance || std::fabs((end - c).norm() - r) > 1e-4) continue;
        if (e.radius && std::fabs(*e.radius - r) > 1e-4) continue;
        Segment s{kind, chain.start, end, c, -1};
        if (e.tangent && chain.direction && (s.startTangent() - *chain.direction).norm() > 1e-4)
            continue;
        out.candidates.push_back(s);
    }
    if (out.candidates.empty())
        return fail(ElementState::Overdetermined,
                    "start, end, centre and radius do not fit one circle");
    return out;
}

/// A following LINE ... TAN to a known end point leaves only the candidates
/// whose end tangent points towards that end point.
Outcome keepTangentToNext(Outcome out, const ContourElement* next) {
    if (!next || next->kind != ElementKind::Line || !next->tangent || next->angle) return out;
    const std::optional<Point> end = fullEnd(*next);
    if (!end) return out;
    std::vector<Segment> kept;
    for (const Segment& s : out.candidates)
        if (s.endTangent().dot(*end - s.end) > kTolerance) kept.push_back(s);
    if (kept.empty())
        return fail(ElementState::Overdetermined,
                    "the next LINE cannot leave tangentially towards its end point");
    out.candidates = kept;
    return out;
}

Outcome solvePrimary(const ContourElement& e, const ContourElement* next, const ChainState& chain) {
    std::string problem;
    std::optional<Point> dir;
    std::vector<Point> centres;
    if (e.kind == ElementKind::Line)
        dir = lineDirection(e, chain, problem);
    else
        centres = arcCentres(e, chain, problem);
    if (!problem.empty()) return fail(ElementState::Overdetermined, problem);
    std::vector<Point> points;
    if (auto end = fullEnd(e)) {
        std::vector<Locus> extra;
        ownLoci(e, chain, dir, centres, extra);
        for (std::size_t i = 2; i < extra.size(); ++i)
            if (!extra[i].contains(*end))
                return fail(ElementState::Overdetermined,
                            "the end point contradicts the other data");
        if (e.kind == ElementKind::Line && dir && (*end - chain.start).dot(*dir) <= kTolerance)
            return fail(ElementState::Overdetermined, "the end point is not in direction A");
        points.push_back(*end);
    } else {
        std::vector<Locus> loci;
        ownLoci(e, chain, dir, centres, loci);
        nextLoci(e, next, dir, centres, loci);
        Outcome found = endPoints(loci, e, chain, dir, points);
        if (found.state != ElementState::Solved) return found;
    }
    Outcome out;
    for (const Point& p : points) {
        if ((p - chain.start).norm() < kTolerance && e.kind == ElementKind::Line) continue;
        if (e.kind == ElementKind::Line) {
            out.candidates.push_back({Segment::Line, chain.start, p, Point::Zero(), -1});
            continue;
        }
        Outcome arcs = arcCandidates(e, chain, p, centres);
        if (arcs.state != ElementState::Solved && points.size() == 1) return arcs;
        out.candidates.insert(out.candidates.end(), arcs.candidates.begin(), arcs.candidates.end());
    }
    if (out.candidates.empty()) return fail(ElementState::Impossible, "the element has no length");
    return keepTangentToNext(out, next);
}

}  // namespace

const char* stateCode(ElementState state) {
    switch (state) {
        case ElementState::Undetermined:
            return "GNE_UNDERDETERMINED";
        case ElementState::Overdetermined:
            return "GNE_OVERDETERMINED";
        case ElementState::Impossible:
            return "GNE_IMPOSSIBLE";
        default:
            return "GNE_NOT_SOLVED";
    }
}

const char* stateName(ElementState state) {
    switch (state) {
        case ElementState::Solved:
            return "solved";
        case ElementState::Undetermined:
            return "undetermined";
        case ElementState::Overdetermined:
            return "overdetermined";
        case ElementState::Impossible:
            return "impossible";
        case ElementState::NotReached:
            return "not reached";
    }
    return "?";
}

ContourSolution solveContour(const Contour& contour) {
    ContourSolution solution;
    const auto& elements = contour.elements;
    solution.elements.resize(elements.size());
    std::vector<Segment> primary;
    ChainState chain;
    bool blocked = elements.empty() || elements[0].kind != ElementKind::Start;
    for (std::size_t i = 0; i < elements.size() && !blocked; ++i) {
        const ContourElement& e = elements[i];
        ElementSolution& out = solution.elements[i];
        if (!isPrimary(e.kind)) continue;
        if (e.kind == ElementKind::Start) {
            chain.start = Point(e.end[0].value_or(0), e.end[1].value_or(0));
            out.state = ElementState::Solved;
            continue;
        }
        const ContourElement* next = nullptr;
        for (std::size_t j = i + 1; j < elements.size() && !next; ++j)
            if (isPrimary(elements[j].kind)) next = &elements[j];
        Outcome found = solvePrimary(e, next, chain);
        out.state = found.state;
        out.message = found.message;
        out.candidates = found.candidates;
        if (found.state == ElementState::Solved &&
            e.alternative >= static_cast<int>(found.candidates.size())) {
            out.state = ElementState::Overdetermined;
            out.message = "ALT" + std::to_string(e.alternative) + " does not exist (" +
                          std::to_string(found.candidates.size()) + " solutions)";
        }
        if (out.state != ElementState::Solved) {
            blocked = true;
            break;
        }
        out.chosen = e.alternative;
        Segment s = found.candidates[static_cast<std::size_t>(e.alternative)];
        s.source = static_cast<int>(i);
        primary.push_back(s);
        chain.start = s.end;
        chain.direction = s.endTangent();
    }
    if (blocked) {
        for (std::size_t i = 0; i < elements.size(); ++i) {
            ElementSolution& out = solution.elements[i];
            if (out.state == ElementState::Solved) continue;
            if (out.state != ElementState::NotReached) {
                solution.diagnostics.push_back(
                    {elements[i].line, stateCode(out.state),
                     std::string(elementKeyword(elements[i].kind)) + ": " + out.message});
            } else {
                out.message = "follows an element that is not solved";
            }
        }
        if (elements.empty() || elements[0].kind != ElementKind::Start)
            solution.diagnostics.push_back(
                {contour.line, "GNE_NO_START", "a contour begins with START"});
        return solution;
    }
    applyTransitions(contour, std::move(primary), solution);
    return solution;
}

}  // namespace mtc::core::gne
