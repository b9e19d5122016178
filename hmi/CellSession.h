#pragma once

#include <QObject>
#include <QString>
#include <QStringList>
#include <QTimer>
#include <cstdint>
#include <memory>
#include <vector>

#include "cnc_core/language/Program.h"
#include "cnc_core/machine/AxisTransfer.h"
#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/machine/ProcessControl.h"
#include "cnc_core/program/ProgramStore.h"
#include "cnc_core/tooldata/SetupData.h"

namespace mtc::core {
class AdaptiveFeedControl;
class AfcTrendRecorder;
class Interpreter;
class MachineDataStore;
class SharedMachineDataFile;
class SimulatedMachine;
}  // namespace mtc::core

namespace mtc::hmi {

class SimulationClock;
class NcOptionsHolder;

/// The simulated cell behind the panel: machine configuration, program
/// memory (parsed programs), and per process its ProcessControl, its
/// interpreter on a simulated machine and the simulation clock that steps
/// it. Screens read it and send machine keys to it; it tells everybody when
/// a process changed.
class CellSession : public QObject {
    Q_OBJECT
  public:
    explicit CellSession(mtc::core::MachineConfig config, QObject* parent = nullptr);
    ~CellSession() override;

    const mtc::core::MachineConfig& config() const { return config_; }
    int processCount() const { return static_cast<int>(config_.processes.size()); }
    /// Process config by station slot (0..processCount-1).
    const mtc::core::ProcessConfig& processConfig(int slot) const;
    mtc::core::ProcessControl& control(int slot);
    const mtc::core::ProcessControl& control(int slot) const;
    mtc::core::Interpreter& interpreter(int slot);
    mtc::core::SimulatedMachine& machine(int slot);
    SimulationClock& clock(int slot);
    /// Adaptive feed control of a station (page 30, signals, errors 508-510).
    mtc::core::AdaptiveFeedControl& adaptiveFeed(int slot);
    /// The adaptive feed trend the station's simulated machine records.
    const mtc::core::AfcTrendRecorder& afcTrend(int slot) const;
    const mtc::core::ProgramStore& store() const { return store_; }

    /// Parses `text` and stores it as program `number` of the station.
    void addProgram(int slot, int number, const std::string& name, std::string text);
    /// Stores an already parsed program (used by the loaders).
    void putProgram(int slot, int number, mtc::core::ProgramPtr program);
    /// Programs of a station ordered by number.
    std::vector<mtc::core::ProgramPtr> programs(int slot) const;
    mtc::core::ProgramPtr program(int slot, int number) const;
    /// Station slot of process number `process`, or -1.
    int slotOfProcess(int process) const;
    /// The program store, for loaders filling it before the panel starts.
    mtc::core::ProgramStore& mutableStore() { return store_; }
    /// Directory the station programs were loaded from ("" = built-in demo
    /// programs: the editor and the compiler write no files for them).
    const QString& programDirectory() const { return programDirectory_; }
    /// Sets the directory programs are saved to (with .NCO/.ERR beside them).
    /// Also loads the cell's NC options from it (ncOptions()).
    void setProgramDirectory(const QString& directory);
    /// The NC options of the cell, shared by both stations (seed 001 ch. 4, 7, 8).
    NcOptionsHolder& ncOptions() { return *ncOptions_; }

    /// Sends a machine control key to a station and announces the change.
    bool pressKey(int slot, mtc::core::ControlKey key);
    /// Selects a program of a station (refused while active).
    bool selectProgram(int slot, int number);
    /// Announce that something of the station changed (screens refresh).
    void notifyChanged(int slot) { emit processChanged(slot); }

    /// The GAX / FAX handshake between the stations' processes (NC program
    /// restart's computing processes wait on it, seed 000, 5.4).
    mtc::core::AxisTransfer& axisTransfer() { return axisTransfer_; }
    /// The machine data of the cell, shared by every station's interpreter.
    mtc::core::MachineDataStore& machineData() { return *machineData_; }
    /// Tool lists and zero offsets of every process; the interpreters read them.
    mtc::core::SetupData& setupData() { return setupData_; }
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

  signals:
    void processChanged(int slot);
    /// Values of the machine data file another program changed were taken
    /// over (`message` says how many and from which file).
    void machineDataNotice(const QString& message);

  private:
    struct Station;
    mtc::core::MachineConfig config_;
    mtc::core::ProgramStore store_;
    mtc::core::AxisTransfer axisTransfer_;
    std::shared_ptr<mtc::core::MachineDataStore> machineData_;
    mtc::core::SetupData setupData_;  ///< tool lists and zero offsets (beside the machine data)
    QString machineDataFile_;
    std::unique_ptr<mtc::core::SharedMachineDataFile> sharedData_;
    QTimer refreshTimer_;  ///< looks for changes of the data file by other programs
    QString programDirectory_;
    QStringList machineDataMessages_;
    QTimer saveTimer_;                 ///< debounces saves of NC-written values
    std::uint64_t savedRevision_ = 0;  ///< store revision the file holds
    QString autoSaveError_;
    std::vector<std::unique_ptr<Station>> stations_;
    std::unique_ptr<NcOptionsHolder> ncOptions_;
};

}  // namespace mtc::hmi
