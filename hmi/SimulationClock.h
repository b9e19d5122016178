#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <functional>

#include "cnc_core/language/Program.h"
#include "cnc_core/machine/ProcessControl.h"

namespace mtc::core {
class Interpreter;
class SimulatedMachine;
}  // namespace mtc::core

namespace mtc::hmi {

/// Steps one process's interpreter in simulated time: every tick it executes
/// blocks until the simulated machine's clock has caught up with real time ×
/// speed (at most a bounded number of blocks per tick, so the GUI stays
/// responsive). It is the ProgramRunner behind the Start/Stop/Reset keys.
class SimulationClock : public QObject, public mtc::core::ProgramRunner {
    Q_OBJECT
  public:
    SimulationClock(mtc::core::Interpreter& interpreter, mtc::core::SimulatedMachine& machine,
                    mtc::core::ProcessControl& control, QObject* parent = nullptr);

    std::string start(int number) override;
    std::string resume() override;
    void hold() override;
    void reset() override;

    /// Makes the runtime program of a number ready before it runs (the
    /// station's ProgramWorkspace: compile on demand, seed 001 ch. 10/11) or
    /// returns an alarm that refuses Start ("" = ready).
    using ProgramPreparer = std::function<std::string(int number)>;
    /// Installs (empty function: removes) the preparer start() calls first.
    void setPreparer(ProgramPreparer preparer) { preparer_ = std::move(preparer); }
    /// Runs the preparer for `number` ("" when none is installed).
    std::string prepare(int number) const { return preparer_ ? preparer_(number) : std::string(); }

    /// Simulated seconds per real second (default 1; tests and demos go faster).
    void setSpeed(double speed) { speed_ = speed > 0 ? speed : 1.0; }
    double speed() const { return speed_; }
    bool running() const { return timer_.isActive(); }
    /// The axis this process waits for (GAX, R-022), "" when none.
    const std::string& waitingAxis() const { return waitingAxis_; }
    /// Runs one tick now (the timer calls this; tests may too).
    void tick();

  signals:
    /// The process's state changed (block, position, end of program).
    void changed();

  private:
    void beginTiming();
    void finish(const std::string& alarm);
    /// True while the interpreter waits for a GAX (R-022): shows "Waiting
    /// for axis X" and keeps ticking without executing blocks.
    bool waitForAxis();
    void showCurrentBlock();

    mtc::core::Interpreter& interpreter_;
    mtc::core::SimulatedMachine& machine_;
    mtc::core::ProcessControl& control_;
    ProgramPreparer preparer_;
    QTimer timer_;
    QElapsedTimer realTime_;
    double simulatedBase_ = 0.0;
    double speed_ = 1.0;
    mtc::core::ProgramPtr lastProgram_;  ///< program and block executed last
    std::uint32_t lastBlock_ = 0;
    std::string waitingAxis_;  ///< axis of the GAX waited for ("" = none)
};

}  // namespace mtc::hmi
