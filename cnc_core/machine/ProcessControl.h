#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cnc_core/machine/SignalTable.h"
#include "cnc_core/text/Messages.h"

namespace mtc::core {

enum class OperatingMode { Automatic, Manual, Mdi };

/// The machine control keys (M keys) of the panel. The panel sends every
/// key through ProcessControl::press; nothing in the GUI changes machine
/// state directly.
enum class ControlKey {
    ProgramRestart,
    Repos,
    Manual,
    Automatic,
    Start,
    Stop,
    ControlReset,
    SingleBlock,  ///< switches single-block mode on / off (PxxCSBLK)
    Mdi,          ///< manual data input mode (Start runs the MDI entry)
};

/// Readable names: "automatic", "manual", "MDI"; "NC program restart", ...
const char* modeName(OperatingMode mode);
const char* keyName(ControlKey key);

/// Runs the selected program of a process (the panel's simulation clock,
/// later the restart logic). ProcessControl calls it for Start/Stop/Reset.
class ProgramRunner {
  public:
    virtual ~ProgramRunner() = default;
    /// Starts program `number` from its first block. Returns "" or an alarm.
    virtual std::string start(int number) = 0;
    /// Starts the MDI entry of the process (MDI mode). Returns "" or an alarm.
    virtual std::string startMdi() { return "Start refused: this station has no MDI input"; }
    /// Continues a held run. Returns "" or an alarm.
    virtual std::string resume() = 0;
    /// Stop key: feed hold; the program stays active.
    virtual void hold() = 0;
    /// Control reset: the run is abandoned, the interpreter reset.
    virtual void reset() = 0;
};

/// Takes the machine control keys before ProcessControl handles them (the
/// NC program restart sequence installs itself while it is active).
class ControlKeyHandler {
  public:
    virtual ~ControlKeyHandler() = default;
    /// Returns the key's result (what press() returns) when it handled the
    /// key, std::nullopt to let ProcessControl handle it as usual.
    virtual std::optional<bool> handleKey(ControlKey key) = 0;
};

/// What a process (station) of the cell is doing, seen from the panel:
/// operating mode, selected program, current alarm and the interface
/// signals. One object per process; no globals.
///
/// Key handling of this layer: Manual/Automatic/MDI switch the mode (refused
/// while a program is active), Start starts the selected program in
/// automatic mode (the MDI entry in MDI mode) through the ProgramRunner (or
/// continues a held one), Stop
/// holds it (PxxSHOLD = 1, the program stays active), Control reset
/// abandons it and clears the alarm; Single block toggles PxxCSBLK at any
/// time (the runner holds after the block); NC program restart toggles the M-key
/// flag mBPREP that the restart logic consumes; REPOS is refused (alarm)
/// unless an NC program restart handles it (RestartSequence).
class ProcessControl {
  public:
    explicit ProcessControl(int process);

    /// Handles one machine control key. Returns false (and sets the alarm)
    /// when the key is not allowed in the current state.
    bool press(ControlKey key);

    int process() const { return process_; }
    OperatingMode mode() const { return mode_; }
    bool programActive() const { return active_; }
    bool programHeld() const { return held_; }
    const std::string& alarm() const { return alarm_; }
    /// What the operator is asked to do in an ordinary state ("Single
    /// block: press Start ..."): a prompt, not an alarm. "" = none.
    const std::string& prompt() const { return prompt_; }
    /// Single-block mode (PxxCSBLK = 1): a running program, the computing
    /// process of NC program restart included, holds after every block.
    bool singleBlock() const;
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
    /// Raises the alarm `code` (ALARM_...): `english`, or its German text
    /// when the language is German, with `values` for "%1"… (alarmText(),
    /// D-025, D-026).
    void raiseAlarm(const char* code, const char* english,
                    const std::vector<std::string>& values = {}) {
        alarm_ = alarmText(code, english, language_, values);
    }
    /// The language of raiseAlarm() and of the core's refusals and prompts
    /// for this station (the panel's; English by default).
    void setLanguage(Language language) { language_ = language; }
    Language language() const { return language_; }
    /// Marks the program as running / finished (sets PxxSACTIV).
    void setProgramActive(bool active);
    /// The runner Start/Stop/Reset act on (not owned; nullptr = none, then
    /// Start raises an alarm).
    void setRunner(ProgramRunner* runner) { runner_ = runner; }
    /// The runner reports the end of the program (or an error that ended it).
    void programFinished(std::string alarm);
    /// The runner reports a programmed stop (M00/M01) or a single-block
    /// hold: the program stays active and held until Start; `message`
    /// becomes the prompt (Start, Control reset and the program end clear it).
    void programStopped(std::string message);
    /// programStopped() with the prompt `code` (PROMPT_...) in the language.
    void programStopped(const char* code, const char* english) {
        programStopped(alarmText(code, english, language_));
    }

    /// Installs (or with nullptr removes) the handler that sees every key
    /// first. Not owned; it must remove itself before it is destroyed.
    void setKeyHandler(ControlKeyHandler* handler) { keyHandler_ = handler; }
    ControlKeyHandler* keyHandler() const { return keyHandler_; }
    /// The SPS selects the operating mode (QMANUAL / QAUTO, e.g. on Q9500 /
    /// Q9501 at the end of ADJUST, seed 000, 2.9 and 7): unlike the Manual and
    /// Automatic keys this is allowed while a program is active (interrupted).
    /// Sets PxxSAUTO / PxxSMANU; never fails.
    void setModeBySps(OperatingMode mode);

    /// "P00" for process 0: the prefix of this process's signal names.
    std::string signalPrefix() const;

  private:
    bool setMode(OperatingMode mode);
    bool start();

    int process_;
    /// PxxCSBLK, asked before every block (built once, not per block).
    std::string singleBlockSignal_;
    /// Its value as of the signal table's change count `singleBlockAt_`: a
    /// map lookup per block was 4 % of a headless run.
    mutable bool singleBlockValue_ = false;
    mutable std::uint64_t singleBlockAt_ = ~std::uint64_t{0};
    OperatingMode mode_ = OperatingMode::Automatic;
    bool active_ = false;
    bool held_ = false;
    ProgramRunner* runner_ = nullptr;
    ControlKeyHandler* keyHandler_ = nullptr;
    int selectedProgram_ = 0;
    std::string currentBlock_;
    std::string alarm_;
    std::string prompt_;
    Language language_ = Language::English;
    SignalTable signals_;
};

}  // namespace mtc::core
