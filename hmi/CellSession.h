#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QTimer>
#include <cstdint>
#include <memory>
#include <vector>

#include "cnc_core/cell/Cell.h"
#include "cnc_core/language/Diagnostic.h"

namespace mtc::core {
class AdaptiveFeedControl;
class AfcTrendRecorder;
class Interpreter;
class MachineDataStore;
class SharedMachineDataFile;
class SetupDataEditor;
class SimulatedMachine;
}  // namespace mtc::core

namespace mtc::hmi {

class NcOptionsHolder;

/// The panel's side of the simulated cell: a thin QObject around the core's
/// Cell (configuration, program memory, machine data and one Station per
/// process, cnc_core/cell). One timer moves every station on in simulated
/// time (real time x the speed factor, or as fast as the computer allows);
/// after each tick it tells the screens which stations changed. It also
/// keeps the panel's files: the machine data file and the program directory.
class CellSession : public QObject {
    Q_OBJECT
  public:
    explicit CellSession(mtc::core::MachineConfig config, QObject* parent = nullptr);
    ~CellSession() override;

    /// The core cell the panel shows and drives.
    mtc::core::Cell& cell() { return cell_; }
    const mtc::core::Cell& cell() const { return cell_; }
    /// Station by slot (0..processCount-1).
    mtc::core::Station& station(int slot) { return cell_.station(slot); }
    const mtc::core::Station& station(int slot) const { return cell_.station(slot); }

    const mtc::core::MachineConfig& config() const { return cell_.config(); }
    int processCount() const { return cell_.stationCount(); }
    /// Process config by station slot (0..processCount-1).
    const mtc::core::ProcessConfig& processConfig(int slot) const;
    mtc::core::ProcessControl& control(int slot) { return station(slot).control(); }
    const mtc::core::ProcessControl& control(int slot) const { return station(slot).control(); }
    mtc::core::Interpreter& interpreter(int slot) { return station(slot).interpreter(); }
    mtc::core::SimulatedMachine& machine(int slot) { return station(slot).machine(); }
    /// Adaptive feed control of a station (page 30, signals, errors 508-510).
    mtc::core::AdaptiveFeedControl& adaptiveFeed(int slot) { return station(slot).adaptiveFeed(); }
    /// The adaptive feed trend the station's simulated machine records.
    const mtc::core::AfcTrendRecorder& afcTrend(int slot) const { return station(slot).afcTrend(); }
    const mtc::core::ProgramStore& store() const { return cell_.store(); }

    /// The programs of station `slot` changed in the cell itself (a save of
    /// the station's compilation): screens refresh.
    void announcePrograms(int slot);
    /// Parses `text` (knowing the global macro names) and stores it as
    /// program `number` of the station.
    void addProgram(int slot, int number, const std::string& name, std::string text);
    /// Stores an already parsed program (used by the loaders).
    void putProgram(int slot, int number, mtc::core::ProgramPtr program);
    /// Programs of a station ordered by number.
    std::vector<mtc::core::ProgramPtr> programs(int slot) const { return cell_.programs(slot); }
    mtc::core::ProgramPtr program(int slot, int number) const {
        return cell_.program(slot, number);
    }
    /// Station slot of process number `process`, or -1.
    int slotOfProcess(int process) const { return cell_.slotOfProcess(process); }
    /// The program store, for loaders filling it before the panel starts.
    mtc::core::ProgramStore& mutableStore() { return cell_.store(); }
    /// Directory the station programs were loaded from ("" = built-in demo
    /// programs: the editor and the compiler write no files for them).
    const QString& programDirectory() const { return programDirectory_; }
    /// Sets the directory programs are saved to (with .NCO/.ERR beside them).
    /// Also loads the cell's NC options from it (ncOptions()).
    void setProgramDirectory(const QString& directory);
    /// Problems the program loader found with files of the program
    /// directory (unreadable, not a file, bad name, duplicate, stale
    /// temporary removed): every station's error window lists them.
    void setLoadProblems(mtc::core::DiagnosticList problems) {
        loadProblems_ = std::move(problems);
    }
    const mtc::core::DiagnosticList& loadProblems() const { return loadProblems_; }
    /// The NC options of the cell, shared by both stations (seed 001 ch. 4, 7, 8).
    NcOptionsHolder& ncOptions() { return *ncOptions_; }

    /// Sends a machine control key to a station and announces the change.
    bool pressKey(int slot, mtc::core::ControlKey key);
    /// Selects a program of a station (refused while active).
    bool selectProgram(int slot, int number);
    /// Announce that something of the station changed (screens refresh).
    void notifyChanged(int slot) { emit processChanged(slot); }

    // ---- simulated time
    /// Simulated seconds per real second; 0 (kMaxSpeed) = as fast as possible.
    void setSpeed(double factor);
    double speed() const { return speed_; }
    static constexpr double kMaxSpeed = 0.0;
    /// The speed key: x1 -> x10 -> as fast as possible -> x1.
    void cycleSpeed();
    /// "x1", "x10", "max" (the header shows it).
    QString speedText() const;
    /// The timer that moves the stations (on by default; tests that step the
    /// time themselves switch it off and call advance()).
    void setTimerEnabled(bool enabled);
    /// Moves every station on by `seconds` of simulated time now and
    /// announces the stations that changed (what the timer does each tick).
    void advance(double seconds);
    /// Interval of the timer, ms (50 Hz).
    static constexpr int kTickMs = 20;

    /// The GAX / FAX handshake between the stations' processes (NC program
    /// restart's computing processes wait on it, seed 000, 5.4).
    mtc::core::AxisTransfer& axisTransfer() { return cell_.axisTransfer(); }
    /// The machine data of the cell, shared by every station's interpreter.
    mtc::core::MachineDataStore& machineData() { return cell_.machineData(); }
    /// Tool lists and zero offsets of every process; the interpreters read them.
    mtc::core::SetupData& setupData() { return cell_.setupData(); }
    const mtc::core::SetupData& setupData() const { return cell_.setupData(); }
    /// Every operator change of the tool lists and zero offsets goes through
    /// it: checked, effective for the next block, saved beside the machine
    /// data file under its lock (not kept without a machine data file).
    mtc::core::SetupDataEditor& setupEditor() { return *setupEditor_; }
    /// Keeps the machine data in `path` from now on: loads it (a damaged
    /// file is kept aside, the defaults stay) and returns what the user must
    /// be told (also kept in machineDataMessages()). Empty path: nothing is kept.
    QStringList openMachineDataFile(const QString& path);
    /// Writes the machine data to its file (no-op without one). False with
    /// `error` when it cannot (then the file on disk is the old one). Values
    /// another program (`mtc200-cli md set`, a second panel) wrote to the
    /// file meanwhile are taken over first, never overwritten with this
    /// panel's older copy (CF-021); machineDataMessages() says so.
    bool saveMachineData(QString& error);
    /// Looks whether another program changed the data file and takes its
    /// values over (the panel checks every kRefreshMs). Returns how many.
    int refreshMachineData();
    /// Takes over the tool lists and zero offsets another program (`tools
    /// set`, a second panel) saved to the files beside the data file; the
    /// panel checks every kRefreshMs with the machine data.
    void refreshSetupData();
    /// Interval of the check for changes by other programs.
    static constexpr int kRefreshMs = 1000;
    /// True while values changed since the last save or load (MTD writes of
    /// NC programs, page 30 status): they are saved within kNcSaveDelayMs and
    /// when the session ends.
    bool machineDataUnsaved() const;
    /// The reason the last automatic save failed ("" = none).
    const QString& autoSaveError() const { return autoSaveError_; }
    /// Delay of the automatic save after the NC changed machine data.
    static constexpr int kNcSaveDelayMs = 1000;
    /// The file the machine data is kept in ("" = none).
    QString machineDataFile() const { return machineDataFile_; }
    /// Messages of the last openMachineDataFile() (damaged file, ignored
    /// values) and of the last take-over of another program's changes.
    const QStringList& machineDataMessages() const { return machineDataMessages_; }

    /// Announces every station whose revision changed since the last look
    /// (after a screen forwarded an operator's action to a station).
    void announceChanges();

  signals:
    void processChanged(int slot);
    /// Values of the machine data file another program changed were taken
    /// over (`message` says how many and from which file).
    void machineDataNotice(const QString& message);
    /// Tool lists or zero offsets of the files were taken over, or a file
    /// another program wrote is refused (`message` says which).
    void setupDataNotice(const QString& message);
    /// The speed factor changed.
    void speedChanged();

  private:
    void tick();
    /// True when `state` holds for one of the stations.
    bool anyStation(bool (mtc::core::Station::*state)() const) const;

    mtc::core::Cell cell_;
    QTimer timer_;
    QElapsedTimer realTime_;
    double speed_ = 1.0;
    std::vector<std::uint64_t> announced_;  ///< station revisions last announced
    QString machineDataFile_;
    std::unique_ptr<mtc::core::SharedMachineDataFile> sharedData_;
    QTimer refreshTimer_;  ///< looks for changes of the data file by other programs
    QString programDirectory_;
    mtc::core::DiagnosticList loadProblems_;
    QStringList machineDataMessages_;
    QTimer saveTimer_;                 ///< debounces saves of NC-written values
    std::uint64_t savedRevision_ = 0;  ///< store revision the file holds
    QString autoSaveError_;
    std::unique_ptr<NcOptionsHolder> ncOptions_;
    std::unique_ptr<mtc::core::SetupDataEditor> setupEditor_;
};

}  // namespace mtc::hmi
