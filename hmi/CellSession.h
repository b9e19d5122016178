#pragma once

#include <QObject>
#include <QString>
#include <map>
#include <memory>
#include <vector>

#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/machine/ProcessControl.h"

namespace mtc::hmi {

/// The source text of one program as the panel knows it.
struct ProgramSource {
    int number = 0;
    QString fileName;
    QString text;
};

/// The simulated cell behind the panel: machine configuration, program
/// memory and one ProcessControl per process. Screens read it and send
/// machine keys to it; it tells everybody when a process changed.
class CellSession : public QObject {
    Q_OBJECT
  public:
    explicit CellSession(mtc::core::MachineConfig config, QObject* parent = nullptr);

    const mtc::core::MachineConfig& config() const { return config_; }
    int processCount() const { return static_cast<int>(config_.processes.size()); }
    /// Process config by station slot (0..processCount-1).
    const mtc::core::ProcessConfig& processConfig(int slot) const;
    mtc::core::ProcessControl& control(int slot) { return *controls_.at(slot); }
    const mtc::core::ProcessControl& control(int slot) const { return *controls_.at(slot); }

    /// Adds or replaces a program of a station.
    void addProgram(int slot, ProgramSource program);
    /// Programs of a station ordered by number.
    std::vector<const ProgramSource*> programs(int slot) const;
    const ProgramSource* program(int slot, int number) const;

    /// Sends a machine control key to a station and announces the change.
    bool pressKey(int slot, mtc::core::ControlKey key);
    /// Selects a program of a station (refused while active).
    bool selectProgram(int slot, int number);
    /// Announce that something of the station changed (screens refresh).
    void notifyChanged(int slot) { emit processChanged(slot); }

  signals:
    void processChanged(int slot);

  private:
    mtc::core::MachineConfig config_;
    std::vector<std::unique_ptr<mtc::core::ProcessControl>> controls_;
    std::vector<std::map<int, ProgramSource>> programs_;
};

}  // namespace mtc::hmi
