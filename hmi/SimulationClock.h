#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <functional>

#include "cnc_core/language/Program.h"
#include "cnc_core/machine/ProcessControl.h"
#include "cnc_core/mdi/MdiRun.h"

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
    /// MDI mode: runs the entry the MDI source gives from the station's
    /// current state (MdiRun, MDI-002).
    std::string startMdi() override;
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

    /// Gives the program of the station's MDI entry for Start in MDI mode,
    /// or an alarm that refuses Start ("" = the program is set).
    using MdiSource = std::function<std::string(mtc::core::ProgramPtr& program)>;
    /// Installs (empty function: removes) the MDI source (the MDI screen).
    void setMdiSource(MdiSource source) { mdiSource_ = std::move(source); }
    /// True while an MDI entry runs (or is held).
    bool mdiRunning() const { return mdiRunning_; }
    /// Diagnostics of the last MDI run (lines = lines of the MDI input).
    const mtc::core::DiagnosticList& lastMdiDiagnostics() const { return mdiDiagnostics_; }

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
    /// The MDI entry ended: `completed` false after an error or Control
    /// reset (lastMdiDiagnostics() has the errors).
    void mdiEnded(bool completed);

  private:
    void beginTiming();
    void finish(const std::string& alarm);
    /// End of an MDI run: the alarm names the MDI line, mdiEnded is sent.
    void finishMdi(const mtc::core::RunResult& result);
    /// True while the interpreter waits for a GAX (R-022): shows "Waiting
    /// for axis X" and keeps ticking without executing blocks.
    bool waitForAxis();
    void showCurrentBlock();

    mtc::core::Interpreter& interpreter_;
    mtc::core::SimulatedMachine& machine_;
    mtc::core::ProcessControl& control_;
    ProgramPreparer preparer_;
    MdiSource mdiSource_;
    mtc::core::MdiRun mdi_;
    bool mdiRunning_ = false;
    mtc::core::DiagnosticList mdiDiagnostics_;
    QTimer timer_;
    QElapsedTimer realTime_;
    double simulatedBase_ = 0.0;
    double speed_ = 1.0;
    mtc::core::ProgramPtr lastProgram_;  ///< program and block executed last
    std::uint32_t lastBlock_ = 0;
    std::string waitingAxis_;  ///< axis of the GAX waited for ("" = none)
};

}  // namespace mtc::hmi
