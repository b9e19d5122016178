#pragma once

#include <array>
#include <string>
#include <vector>

#include "cnc_core/interp/MachineSink.h"

namespace mtc::core {

class Interpreter;
class ProcessControl;
class SimulatedMachine;

/// The jog increments of the panel, mm (degrees for rotary axes); one press
/// of a jog key or one handwheel detent (times its factor) moves this far.
inline constexpr std::array<double, 5> kJogIncrements = {0.001, 0.01, 0.1, 1.0, 10.0};

/// The spindle keys of manual mode (MOT-018).
enum class SpindleKey { Clockwise, CounterClockwise, Stop, Faster, Slower };
/// Speed of a manual start when none is commanded, and one Faster/Slower step (rpm).
inline constexpr double kManualSpindleStart = 500.0;
inline constexpr double kManualSpindleStep = 100.0;

/// Jogging in manual mode (issue 17 §2, docs/decisions/motion.md MOT-017):
/// the axes move through the station's machine in time, at the jog feed
/// (a fifth of the axis's max_velocity, under the feed override) or, with
/// the rapid key, at its max_velocity (under the rapid override). A target
/// beyond the travel limits is refused with the reason; a continuous jog
/// runs to the limit at most and stops there. When the axes are at rest the
/// interpreter takes their positions (the next program or MDI block starts
/// there) and Bxx.036 = Yes cancels the program's state as the seed says
/// (seed 000, 2.9). Every refusal is a sentence for the alarm line, in the
/// station's language (ProcessControl::language()).
class ManualJog {
  public:
    ManualJog(ProcessControl& control, Interpreter& interpreter, SimulatedMachine& machine);

    /// Moves machine axis `axis` by `distance` ("" when the move is queued).
    std::string moveBy(int axis, double distance, bool rapid);
    /// A jog key held down: `axis` moves in `direction` (+1 / -1) until
    /// release() or its travel limit.
    std::string start(int axis, int direction, bool rapid);
    /// The jog key is released: the axis brakes on its path and stops.
    void release();
    /// After the machine's time: ends a braked continuous jog and hands the
    /// positions to the interpreter once the axes stand. True when the
    /// machine dropped the braked jog's move (it ends where the axes stopped).
    bool settle();
    /// A jog move is queued or running.
    bool moving() const { return moving_; }
    /// The move moveBy() or start() queued last (machine axes, no tool data).
    const Motion& lastMove() const { return lastMove_; }
    /// Manual spindle (MOT-018): `rotation` +1 clockwise (M3), -1
    /// counter-clockwise (M4), 0 stop (M5) of spindle `spindle` (1..3) at
    /// `rpm` (kept when negative), through the machine and its SPS as the
    /// M and S functions of a program would go.
    std::string spindle(int spindle, int rotation, double rpm);
    /// A spindle key: M3 / M4 (at the start speed when none is commanded),
    /// M5, or the speed one step up or down in the present direction. Keys
    /// pressed faster than the machine executes them build on each other.
    std::string spindleKey(int spindle, SpindleKey key);

  private:
    std::string check(int axis) const;
    std::string queue(int axis, double target, bool rapid);
    /// A refusal with the stable code `code` in the station's language
    /// (alarmText(), docs/DECISIONS.md D-026).
    std::string refusal(const char* code, const char* english,
                        const std::vector<std::string>& values = {}) const;

    ProcessControl& control_;
    Interpreter& interpreter_;
    SimulatedMachine& machine_;
    /// What each spindle was told last by the keys (+1 / -1 / 0, rpm), while
    /// the machine has not yet executed it; the machine's own state otherwise.
    struct SpindleCommand {
        int rotation = 0;
        double rpm = 0.0;
    };
    SpindleCommand commandOf(int spindle) const;
    std::array<SpindleCommand, 4> told_{};
    Motion lastMove_;
    bool moving_ = false;
    bool releasing_ = false;  ///< a continuous jog brakes (hold) until at rest
};

}  // namespace mtc::core
