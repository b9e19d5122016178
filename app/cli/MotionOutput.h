#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "cli/JsonWriter.h"
#include "cnc_core/interp/MachineSink.h"

namespace mtc::core {
class AdaptiveFeedControl;
class SimulatedMachine;
}  // namespace mtc::core

namespace mtc::cli {

/// How `run` reports motion while the program runs.
enum class MotionMode { None, Json, Text };

/// The sink `run` hands to the interpreter: every motion is written at once
/// (JSON array entries or text lines) so a run of a million motions streams
/// instead of piling up; with MotionMode::None motions are only counted.
/// Auxiliary functions, dwells and commands are counted.
class MotionOutput : public core::MachineSink {
  public:
    /// `json` must have an open array when mode is Json; `text` is used in
    /// Text mode.
    MotionOutput(MotionMode mode, JsonWriter* json, std::FILE* text);

    /// Names of the machine axes in Motion::end order; "" leaves an axis out.
    /// Set before the first motion arrives.
    void setAxisNames(std::vector<std::string> names) { names_ = std::move(names); }

    /// The station's machine, which has just taken each move and dwell (the
    /// station calls its listener after the machine): moves under adaptive
    /// feed control (G26, or with ITM) show the feed the axes really got
    /// ("AFC F=..." / "afc_feed") and, when an error stopped them, the point
    /// where they stopped (" stopped" / "afc_stopped").
    void attachAdaptiveFeed(const core::SimulatedMachine* machine,
                            const core::AdaptiveFeedControl* afc) {
        machine_ = machine;
        afc_ = afc;
    }

    void motion(const core::Motion& motion) override;
    void auxiliary(const core::AuxOutput& output) override;
    void dwell(const core::SourceLocation& where, double seconds) override;
    void command(const core::MachineCommand& command) override;

    /// False with MotionMode::None: the run does not produce motion at all
    /// (--no-motion), so motionCount() means nothing.
    bool reportsMotion() const { return mode_ != MotionMode::None; }
    std::uint64_t motionCount() const { return motions_; }
    std::uint64_t auxiliaryCount() const { return auxiliaries_; }
    std::uint64_t dwellCount() const { return dwells_; }
    double dwellSeconds() const { return dwellSeconds_; }
    std::uint64_t commandCount() const { return commands_; }

    /// "rapid", "linear", "cw" or "ccw".
    static const char* typeName(core::MotionType type);

  private:
    void writeJson(const core::Motion& motion);
    /// `key`: {axis name: value(axis)} over the reported axes of `motion`.
    void writeAxes(const char* key, const core::Motion& motion,
                   const std::function<double(int)>& value);
    /// Centre coordinate of a circle as the records give it: the programmed
    /// circle's (tool compensation moves the axes' circle by the tool offset).
    static double centreOf(const core::Motion& motion, int axis, double centre);
    void writeText(const core::Motion& motion);
    const std::string& axisName(int index) const;
    void appendAxisValue(int axis, double value);

    bool adaptedMotion(const core::Motion& motion);

    MotionMode mode_;
    const core::SimulatedMachine* machine_ = nullptr;
    const core::AdaptiveFeedControl* afc_ = nullptr;
    bool adapted_ = false;  ///< the current motion went through adaptive feed control
    bool stopped_ = false;  ///< ... and an error stopped it short of its end
    JsonWriter* json_;
    std::FILE* text_;
    std::vector<std::string> names_;  ///< per machine axis; "" = leave out
    std::string line_;                ///< reused text line
    std::uint64_t motions_ = 0;
    std::uint64_t auxiliaries_ = 0;
    std::uint64_t dwells_ = 0;
    double dwellSeconds_ = 0.0;
    std::uint64_t commands_ = 0;
};

}  // namespace mtc::cli
