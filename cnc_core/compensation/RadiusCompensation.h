#pragma once

// Tool radius compensation G40/G41/G42 of the working plane as a stream:
// the programmed plane moves go in one by one, the tool-centre path comes
// out with the elements the control inserts at outer corners. One move is
// held back (its end depends on the next move's start); everything else is
// released at once, so the work and memory per block are constant. A value
// type: the interpreter plans a block on a copy and keeps it on commit.
// Decisions: docs/decisions/compensation.md (TC-xxx).

#include <array>
#include <string>

#include "cnc_core/compensation/PlanePath.h"

namespace mtc::core::comp {

/// G41: the tool is left of the contour (seen in the direction of travel,
/// looking from the positive perpendicular axis), G42 right, G40 none.
enum class Side : signed char { None = 0, Left = 1, Right = -1 };

/// One plane move of the programmed path entering the compensation.
struct ContourMove {
    /// Programmed path in plane coordinates. For Side::None the path of the
    /// tool centre itself (the caller shifts it by a lathe edge offset).
    PlanePath path;
    Side side = Side::None;  ///< compensation in effect for this move
    double radius = 0.0;     ///< tool radius (mm, >= 0)
    bool rapid = false;      ///< G0
    int id = 0;              ///< the caller's reference, handed back with pieces and problems
};

/// A piece of the tool-centre path.
struct ToolPiece {
    PlanePath path;
    int id = 0;  ///< the move it belongs to (an inserted piece: the move before the corner)
    bool inserted = false;  ///< a corner element the control inserts (the runtime program's arrow)
};

/// The tool-centre pieces one step releases, in order. Blocks queued behind
/// the move that was held take place after the first `beforeQueued` pieces,
/// with the tool at `queuedAt`.
struct Release {
    std::array<ToolPiece, 4> pieces{};
    int count = 0;
    int beforeQueued = 0;
    Vec2 queuedAt = Vec2::Zero();

    void add(const ToolPiece& piece) { pieces[static_cast<std::size_t>(count++)] = piece; }
};

/// Why a contour cannot be followed (stable code, message, the move at fault).
struct Problem {
    const char* code = nullptr;
    std::string message;
    int id = 0;       ///< the move at fault
    int otherId = 0;  ///< the other move involved (bottleneck), 0 = none
};

/// Where the compensation stands.
enum class Phase : unsigned char {
    Off,      ///< G40: moves pass as they are (from the tool's position when it is displaced)
    Startup,  ///< G41/G42 selected, the next plane move is the start-up move
    Active,   ///< a move is held until the next one shows how its end joins
    Resume,   ///< the contour was interrupted: the tool stands at the perpendicular of the last end
};

class RadiusCompensation {
  public:
    /// Elements of the tool path kept for the bottleneck check.
    static constexpr int kWindow = 8;

    /// Takes `move`: what it releases, or why it cannot be followed (then
    /// the state is undefined: the caller plans on a copy, a small value).
    bool apply(const ContourMove& move, Release& release, Problem& problem);

    /// True when `move` would be a contour element that has no direction (a
    /// straight move of zero length while the contour runs): the caller
    /// treats it like a block without plane motion.
    bool ignores(const ContourMove& move) const;

    /// Ends the held move at the perpendicular of its end (M00, too many
    /// blocks without plane motion): the tool stops there.
    /// A tool path that crosses an earlier one (bottleneck) still goes out;
    /// the problem is reported through `problem`.
    Release interrupt(Problem* problem = nullptr);
    /// Interrupts and switches compensation off (program end, control reset
    /// without a cancel move): the tool stays where it is.
    Release stop(Problem* problem = nullptr);
    /// After a change of the coordinate frame (transformation, axis
    /// functions, restored state): nothing held, the tool centre at `tool`
    /// (plane coordinates of the new frame); the next plane move starts up
    /// when compensation is on. `reentry` (REPOS, TC-013): when the tool
    /// stands on the tool path of the next plane move, that move continues
    /// the contour from there instead of starting up.
    void relocate(const Vec2& tool, bool compensationOn, bool reentry = false);
    /// Off, nothing held, no displacement.
    void reset() { state_ = State{}; }

    Phase phase() const { return state_.phase; }
    bool holding() const { return state_.holding; }
    /// Nothing to do: off, the tool on the programmed path.
    bool idle() const { return state_.phase == Phase::Off && !state_.toolKnown; }
    /// Where the tool centre stands after the released pieces (valid unless idle()).
    const Vec2& tool() const { return state_.tool; }

  private:
    struct Held {
        PlanePath programmed;  ///< the programmed move
        PlanePath tool;        ///< its tool path (start fixed, end provisional)
        Side side = Side::None;
        double radius = 0.0;
        bool rapid = false;
        bool startup = false;  ///< the start-up move: its end is the next element's offset start
        int id = 0;
    };
    struct WindowEntry {
        PlanePath tool;
        int id = 0;
    };
    struct State {
        Phase phase = Phase::Off;
        Vec2 tool = Vec2::Zero();
        bool toolKnown = false;  ///< Off: the tool is not where the programmed path starts
        bool holding = false;
        bool reentry = false;  ///< Startup after REPOS: the tool may stand on the next tool path
        Held held;             ///< Active: the held move; Resume: the last move (already released)
        std::array<WindowEntry, kWindow> window{};
        int windowCount = 0, windowNext = 0;
    };

    bool step(State& s, const ContourMove& m, Release& r, Problem& p) const;
    bool off(State& s, const ContourMove& m, Release& r, Problem& p) const;
    bool startup(State& s, const ContourMove& m, Problem& p) const;
    /// Re-entry (TC-013): the tool stands on the tool path of `m`, which is
    /// held from there on as a contour element. False: it does not.
    bool reenter(State& s, const ContourMove& m) const;
    bool firstElement(State& s, const ContourMove& m, Release& r, Problem& p) const;
    bool join(State& s, const ContourMove& m, Release& r, Problem& p) const;
    bool resume(State& s, const ContourMove& m, Release& r, Problem& p) const;
    /// Releases the held move ending at its perpendicular; the tool stops
    /// there. False (and `p`) when that tool path crosses an earlier one.
    bool finishHeld(State& s, Release& r, Problem* p) const;
    bool offsetElement(const ContourMove& m, PlanePath& out, Problem& p) const;
    /// False (and `p`) when the final tool path of move `id` crosses the
    /// tool path of an earlier element of the window (not its neighbour).
    bool bottleneck(const State& s, const PlanePath& tool, int id, Problem& p) const;
    static void remember(State& s, const PlanePath& tool, int id);
    static void hold(State& s, const ContourMove& m, const PlanePath& tool, bool startup);

    State state_;
};

}  // namespace mtc::core::comp
