#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "cnc_core/afc/AfcSettings.h"
#include "cnc_core/afc/AfcTrendRecorder.h"
#include "cnc_core/afc/TorqueModel.h"
#include "cnc_core/machine/SignalTable.h"

namespace mtc::core {

/// Outcome of an adaptive feed control request.
enum class AfcStatus {
    Ok,
    NotAvailable,     ///< Bxx.062 = no
    NoReferenceAxis,  ///< reference axis 0 or not an axis of the process
    Incompatible,     ///< G74, G75, G33, G63..G65, G77, G31, G32 with G26
    ErrorPending,     ///< error 510 waits for Clear Error
    Error508,         ///< idling torque recording: block too short or speed not constant
    Error509,         ///< idling torque > maximum idling torque
    Error510,         ///< 100 % feed reduction for 20 ms
    BadPeriod,        ///< P-7-3651 period outside 0..60000 ms
    FeedStopped,      ///< 100 % reduction allowed (013 = 100 %) and the axes stand for too long
    MoveTooLong,      ///< a move under G26 lasts longer than the simulation allows
};

/// "AFC_ERROR_510", "AFC_INCOMPATIBLE", ... ("" for Ok).
const char* afcStatusCode(AfcStatus status);

/// One controller cycle, for the trend (seed 002 Fig. 2-1).
struct AfcSample {
    double time = 0.0;             ///< s since the control was made
    double torqueActual = 0.0;     ///< S-0-0084, %
    double machiningTorque = 0.0;  ///< 007, %
    double feedReduction = 0.0;    ///< 011, %
    double effectiveFeed = 0.0;    ///< mm/min
};

/// Adaptive feed control of one process (seed 002): G26/G25, ITM, the I
/// controller that reduces the feed when the machining torque of the
/// reference axis exceeds the limiting machining torque, the status elements
/// of page 30, the signals PxxS.THMIS / PxxS.EXCTH, errors 508/509/510, stall
/// torque recording (AXD P-7-3651/3652). The reference axis is simulated by
/// a TorqueModel. Never throws; refusals are statuses with a message().
class AdaptiveFeedControl {
  public:
    /// Reads Bxx.062..069 of `process` (bad values: parameterDiagnostics()).
    /// `signalTable` (may be null) receives PxxSTHMIS and PxxSEXCTH.
    AdaptiveFeedControl(const ProcessConfig& process, MachineDataStore& store,
                        TorqueModelParameters model = {}, SignalTable* signalTable = nullptr);

    const DiagnosticList& parameterDiagnostics() const { return parameterDiagnostics_; }
    /// The settings in force now: page 30 when its element 002 is not 0,
    /// else the process parameters (the precedence rule of seed 002 ch. 5).
    /// The reference is to the remembered settings, which a later call
    /// refreshes in place after the store changed.
    const AfcSettings& effectiveSettings() const;

    /// G26 with the G codes now active. With 002 = 0 the process parameters
    /// are copied into page 30 first (002 = Bxx.063). Sets 001 = 1, 011 = 0,
    /// THMIS = 0. Refused (nothing changes) when Bxx.062 = no, without a
    /// reference axis of the process, with an incompatible function active,
    /// or while error 510 is pending.
    AfcStatus switchOn(const std::vector<int>& activeGCodes = {});
    /// What switchOn() would answer, without changing anything; the reason
    /// of a refusal goes to `reason`.
    AfcStatus checkSwitchOn(const std::vector<int>& activeGCodes, std::string& reason) const;
    /// Bxx.062 = yes: the process has adaptive feed control.
    bool available() const { return parameters_.available; }
    /// G25: 001 = 0, 008 = peak machining torque, 012 = peak feed reduction,
    /// THMIS = 1 if the machining torque never exceeded 009 (not when 009 = 0).
    void switchOff();
    /// End of program: as G25, then THMIS = EXCTH = 0.
    void programEnd();
    /// Control reset: as end of program; a pending error 510 stays.
    void controlReset();
    /// Clear Error: error 510 goes away.
    void clearError();
    /// A block while G26 is active: refused when it has an incompatible G code.
    AfcStatus checkBlock(const std::vector<int>& gCodes);
    /// The NC function a G code stands for when it excludes adaptive feed
    /// control ("thread cutting (G33)", ...), nullptr otherwise.
    static const char* incompatibleFunction(int gCode);

    /// The machine clock (s): the moment the next controller cycle, ITM
    /// sample or stall torque sample belongs to. The simulated machine sets it
    /// at the start of every move; advance() and holdSteady() move it on.
    void setClock(double seconds) { time_ = seconds; }
    /// Called before the interpreter reads the clock (a stall torque
    /// recording): a machine that works its queue off in batches brings the
    /// clock to where it would be without them (MOT-022). Empty: none.
    void setClockSync(std::function<void()> sync) { clockSync_ = std::move(sync); }
    double clock() const { return time_; }

    /// ITM: idling torque of the reference axis over the measuring period
    /// (004 / Bxx.069) from clock() on at `feed`; the block has
    /// `constantSeconds` at constant speed. 005 = mean(M_act - M_stall).
    /// Error 508 when the constant-speed part is shorter than the period or
    /// `speedConstant` is false; error 509 when 005 > 006 (006 != 0).
    /// `engagement` of the tool while measuring (0: in air, as ITM should be).
    AfcStatus measureIdleTorque(double feed, double speedFraction, double constantSeconds,
                                bool speedConstant = true, double engagement = 0.0);
    /// AXD(axis:P-7-3651)=period: stall torque of `axis` over `periodMs`
    /// (correct only when the axis stands still: `feedWhileRecording` 0).
    /// For the reference axis 014 = |result| (seed 002 5.2); the machining
    /// and idling torques are compensated with the signed result (Fig. 5-7).
    AfcStatus recordStallTorque(const std::string& axis, double periodMs,
                                double feedWhileRecording = 0.0);
    /// AXD(axis:P-7-3652): the last recorded stall torque in 0.1 % (0 if none).
    double measuredStallTorque(const std::string& axis) const;

    /// One controller cycle of `dt` seconds while the axes move at
    /// `programmedFeed` (mm/min, already with override) with `engagement`
    /// of the tool. Returns the feed the axes get (the programmed feed when
    /// the control is off, 0 while error 510 is pending).
    double advance(double dt, double programmedFeed, double speedFraction, double engagement);

    /// True when the controller would not change the feed reduction any
    /// more at `programmedFeed` (the noise aside): 007 is at 010, or the
    /// reduction stands at 0 % below the limit or at 100 % above it.
    bool settled(double programmedFeed, double speedFraction, double engagement) const;
    /// The slope of the machining torque over the feed reduction at the
    /// present reduction (% torque per % reduction, >= 0; for step sizes).
    double torqueSlope(double programmedFeed, double speedFraction, double engagement) const;
    /// `seconds` of control in one step, for long moves (AfcMotion): the
    /// reduction follows the noise-free torque with a linearised implicit
    /// Euler step (stable for any step length; a settled controller keeps
    /// its reduction), the clock, the zero-feed time of error 510, the
    /// signals and peaks move on; `samples` (>= 1) noisy samples spread over
    /// the span stand for the cycles and go to `recorder` (may be null).
    /// Returns the feed the axes get at the end of the span.
    double advanceSpan(double seconds, int samples, double programmedFeed, double speedFraction,
                       double engagement, AfcTrendRecorder* recorder);
    /// The feed reduction in force now (0 while G26 is off).
    double effectiveReduction() const { return active_ ? reduction_ : 0.0; }

    /// An error of the machining (508, 509, 510, feed stopped) for the
    /// interpreter to report with the block that caused it.
    void raiseRuntimeError(AfcStatus status, std::string message);
    /// The move of the block that raised the runtime error stopped after
    /// `fraction` (0..1) of its path (AFC-012: the axes stand there).
    void setStopFraction(double fraction) { stopFraction_ = fraction; }
    /// Share of the path of the erroneous block's move that was travelled
    /// (1 when it was not stopped); read with the runtime error.
    double stopFraction() const { return stopFraction_; }
    /// True while a runtime error waits to be reported.
    bool runtimeErrorPending() const { return runtimeError_ != AfcStatus::Ok; }
    /// Hands the waiting runtime error over (status Ok when none); clears it.
    AfcStatus takeRuntimeError(std::string& message);
    /// ITM of the block being executed: the machine measures in its next move.
    void requestIdleMeasurement(bool requested) { idleRequested_ = requested; }
    bool idleMeasurementRequested() const { return idleRequested_; }
    /// The machine tells how much longer (s) the last move took than planned.
    void addExtraSeconds(double seconds) { extraSeconds_ += seconds; }
    /// Extra seconds since the last call (the interpreter adds them to its clock).
    double takeExtraSeconds();

    /// One torque sample of the reference axis at clock() + `offset` while
    /// G26 is off (the trend shows the machining before G26 and the ITM
    /// moves too): 011 stays.
    void observe(double feed, double speedFraction, double engagement, double offset = 0.0);
    /// These torques become the last observed ones (those of the last
    /// sample of an observed move, AfcObservedMove).
    void takeObservation(double torqueActual, double machiningTorque) {
        lastActual_ = torqueActual;
        lastMachining_ = machiningTorque;
    }
    /// The state of the last advance()/observe() as a trend point at `time`;
    /// `measuringIdle`: the sample lies in the measuring period of ITM.
    AfcTrendSample trendSample(double time, double effectiveFeed, bool measuringIdle = false) const;
    /// The same written into `sample` (filled in place where it is kept: a
    /// sample built and then copied stalled on its byte-sized flags).
    void fillTrendSample(AfcTrendSample& sample, double time, double effectiveFeed,
                         bool measuringIdle = false) const;
    /// The stall torque the machining and idling torques are corrected by:
    /// the signed P-7-3652 result of the reference axis while 014 still
    /// shows its absolute value, else 014 as written (operator, MTD).
    double stallCompensation() const;

    bool active() const { return active_; }
    /// G26, ITM or P-7-3651 was executed since construction.
    bool used() const { return used_; }
    bool errorPending() const { return error510_; }
    double feedReduction() const { return reduction_; }
    /// Text of the last refusal or error.
    const std::string& message() const { return message_; }
    const std::vector<AfcSample>& trend() const { return trend_; }
    TorqueModel& model() { return model_; }
    const TorqueModel& model() const { return model_; }

  private:
    bool referenceAxisExists(int significance) const;
    AfcStatus refuse(AfcStatus status, std::string message);
    void deactivate();
    void setSignal(const char* name, int value);
    void setStatus(int element, double value);
    double element(int number) const;
    /// Forgets the remembered page 30 values when the store changed.
    void followStore() const;
    void raise510();
    /// The noise-free machining torque (007) at reduction `reduction`.
    double expectedMachining(double reduction, double programmedFeed, double speedFraction,
                             double engagement) const;
    /// 007, 011, peaks, THMIS memory, EXCTH and the zero-feed time after a
    /// controller step of `dt` seconds that ended with `machining`.
    void afterControl(double dt, double actual, double machining, const AfcSettings& settings);

    const ProcessConfig& process_;
    MachineDataStore& store_;
    /// Page 30 as last read: the controller and the trend read the same
    /// elements thousands of times per move (a third of a headless run went
    /// into the store's lookups). Valid while the store's revision stays,
    /// which every write and every status update that changes a value bumps.
    struct PageMemo {
        std::uint64_t revision = ~std::uint64_t{0};
        std::array<double, 32> value{};
        std::uint32_t known = 0;  ///< bit n: value[n] holds element n
        bool settingsKnown = false;
        AfcSettings settings;
        /// stallCompensation(), asked for every observed move; also forgotten
        /// when a stall torque is recorded.
        bool stallKnown = false;
        double stall = 0.0;
    };
    mutable PageMemo memo_;
    SignalTable* signals_;
    // Declared before parameters_: its initialiser writes into this list
    // (members are constructed in declaration order).
    DiagnosticList parameterDiagnostics_;
    AfcParameters parameters_;
    TorqueModel model_;
    std::map<std::string, double, std::less<>> stallTorques_;  ///< axis -> P-7-3652 value in 0.1 %
    bool active_ = false;
    bool error510_ = false;
    bool minimumExceeded_ = false;
    bool excessiveThrust_ = false;  ///< PxxS.EXCTH as last set
    bool thrustMissing_ = false;    ///< PxxS.THMIS as last set
    double reduction_ = 0.0;
    double peakMachining_ = 0.0;
    double peakReduction_ = 0.0;
    double zeroFeedSeconds_ = 0.0;
    double stopFraction_ = 1.0;
    double lastActual_ = 0.0;          ///< S-0-0084 of the last cycle
    double lastMachining_ = 0.0;       ///< 007 of the last cycle
    double time_ = 0.0;                ///< machine clock, s (setClock)
    std::function<void()> clockSync_;  ///< setClockSync
    std::string message_;
    std::vector<AfcSample> trend_;
    AfcStatus runtimeError_ = AfcStatus::Ok;
    std::string runtimeMessage_;
    bool idleRequested_ = false;
    bool used_ = false;
    double extraSeconds_ = 0.0;
};

}  // namespace mtc::core
