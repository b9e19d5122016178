#pragma once

#include <functional>
#include <string>

#include "cnc_core/machine/SignalTable.h"

namespace mtc::core {

enum class OperatingMode { Automatic, Manual, Mdi };

/// The machine control keys (M keys) of the panel. The panel sends every
/// key through ProcessControl::press; nothing in the GUI changes machine
/// state directly.
enum class ControlKey { ProgramRestart, Repos, Manual, Automatic, Start, Stop, ControlReset };

/// Readable names: "automatic", "manual", "MDI"; "NC program restart", ...
const char* modeName(OperatingMode mode);
const char* keyName(ControlKey key);

/// What a process (station) of the cell is doing, seen from the panel:
/// operating mode, selected program, current alarm and the interface
/// signals. One object per process; no globals.
///
/// Key handling of this layer: Manual/Automatic switch the mode (refused
/// while a program is active), Control reset clears the alarm and stops the
/// program, Stop stops it, Start starts the selected program in automatic
/// mode through the `startProgram` hook; NC program restart and REPOS set
/// the M-key flags mBPREP / mREPOS that the restart logic consumes.
class ProcessControl {
  public:
    explicit ProcessControl(int process);

    /// Handles one machine control key. Returns false (and sets the alarm)
    /// when the key is not allowed in the current state.
    bool press(ControlKey key);

    int process() const { return process_; }
    OperatingMode mode() const { return mode_; }
    bool programActive() const { return active_; }
    const std::string& alarm() const { return alarm_; }
    int selectedProgram() const { return selectedProgram_; }
    const std::string& currentBlock() const { return currentBlock_; }
    const SignalTable& signalTable() const { return signals_; }
    SignalTable& signalTable() { return signals_; }

    /// Selects program `number` (0 = none); refused while a program is active.
    bool selectProgram(int number);
    /// Sets the block shown in the status header (e.g. "N0012").
    void setCurrentBlock(std::string block) { currentBlock_ = std::move(block); }
    /// Raises an alarm (empty text clears it).
    void setAlarm(std::string text) { alarm_ = std::move(text); }
    /// Marks the program as running / finished (sets PxxSACTIV).
    void setProgramActive(bool active);
    /// Called by Start in automatic mode with a selected program; returns an
    /// alarm text or "" on success. Without a hook, Start raises an alarm.
    std::function<std::string(int program)> startProgram;

    /// "P00" for process 0: the prefix of this process's signal names.
    std::string signalPrefix() const;

  private:
    bool setMode(OperatingMode mode);
    bool start();

    int process_;
    OperatingMode mode_ = OperatingMode::Automatic;
    bool active_ = false;
    int selectedProgram_ = 0;
    std::string currentBlock_;
    std::string alarm_;
    SignalTable signals_;
};

}  // namespace mtc::core
