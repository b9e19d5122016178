#include "cnc_core/machine/ProcessControl.h"

#include <cstdio>

namespace mtc::core {

const char* modeName(OperatingMode mode) {
    switch (mode) {
        case OperatingMode::Automatic:
            return "automatic";
        case OperatingMode::Manual:
            return "manual";
        case OperatingMode::Mdi:
            return "MDI";
    }
    return "?";
}

const char* keyName(ControlKey key) {
    switch (key) {
        case ControlKey::ProgramRestart:
            return "NC program restart";
        case ControlKey::Repos:
            return "REPOS";
        case ControlKey::Manual:
            return "Manual";
        case ControlKey::Automatic:
            return "Automatic";
        case ControlKey::Start:
            return "Start";
        case ControlKey::Stop:
            return "Stop";
        case ControlKey::ControlReset:
            return "Control reset";
        case ControlKey::SingleBlock:
            return "Single block";
        case ControlKey::Mdi:
            return "MDI";
    }
    return "?";
}

ProcessControl::ProcessControl(int process)
    : process_(process), singleBlockSignal_(signalPrefix() + "CSBLK") {
    signals_.set(signalPrefix() + "SREADY", 1);
    signals_.set(signalPrefix() + "SAUTO", 1);
    signals_.clearLog();
}

std::string ProcessControl::signalPrefix() const {
    char buffer[8];
    std::snprintf(buffer, sizeof buffer, "P%02d", process_ % 100);
    return buffer;
}

bool ProcessControl::press(ControlKey key) {
    if (keyHandler_) {
        if (const std::optional<bool> handled = keyHandler_->handleKey(key)) return *handled;
    }
    const std::string p = signalPrefix();
    switch (key) {
        case ControlKey::Manual:
            return setMode(OperatingMode::Manual);
        case ControlKey::Automatic:
            return setMode(OperatingMode::Automatic);
        case ControlKey::Mdi:
            return setMode(OperatingMode::Mdi);
        case ControlKey::Start:
            return start();
        case ControlKey::Stop:
            signals_.set(p + "CSTOP", 1);
            if (active_ && !held_) {
                if (runner_) runner_->hold();
                held_ = true;
                signals_.set(p + "SHOLD", 1);
            }
            signals_.set(p + "CSTOP", 0);
            return true;
        case ControlKey::ControlReset:
            signals_.set(p + "CRESET", 1);
            if (runner_) runner_->reset();
            setProgramActive(false);
            alarm_.clear();
            prompt_.clear();
            currentBlock_.clear();
            signals_.set(p + "CRESET", 0);
            return true;
        case ControlKey::ProgramRestart:
            signals_.set("mBPREP", 1 - signals_.get("mBPREP"));
            return true;
        case ControlKey::SingleBlock:
            signals_.set(p + "CSBLK", singleBlock() ? 0 : 1);
            return true;
        case ControlKey::Repos:
            // Without an NC program restart past its computing process there is
            // nothing to reposition to: the SPS would not set PxxCREPOS.
            raiseAlarm("ALARM_REPOS_NO_RESTART",
                       "REPOS refused: no multi-block retrace possible (no NC program restart "
                       "has reached its target block)");
            return false;
    }
    return false;
}

bool ProcessControl::singleBlock() const {
    if (singleBlockAt_ != signals_.changes()) {
        singleBlockValue_ = signals_.get(singleBlockSignal_) == 1;
        singleBlockAt_ = signals_.changes();
    }
    return singleBlockValue_;
}

bool ProcessControl::setMode(OperatingMode mode) {
    if (active_ && mode != mode_) {
        raiseAlarm("ALARM_MODE_PROGRAM_ACTIVE",
                   "Mode change refused: a program is active (press Stop first)");
        return false;
    }
    setModeBySps(mode);
    return true;
}

void ProcessControl::setModeBySps(OperatingMode mode) {
    mode_ = mode;
    const std::string p = signalPrefix();
    signals_.set(p + "SAUTO", mode == OperatingMode::Automatic ? 1 : 0);
    signals_.set(p + "SMANU", mode == OperatingMode::Manual ? 1 : 0);
}

bool ProcessControl::start() {
    const std::string p = signalPrefix();
    const bool mdi = mode_ == OperatingMode::Mdi;
    if (mode_ == OperatingMode::Manual) {
        raiseAlarm("ALARM_START_NOT_AUTOMATIC", "Start refused: select automatic mode first");
        return false;
    }
    if (!mdi && selectedProgram_ == 0) {
        raiseAlarm("ALARM_START_NO_PROGRAM", "Start refused: no program selected");
        return false;
    }
    if (active_ && !held_) return true;  // already running
    if (!runner_) {
        raiseAlarm("ALARM_START_NO_CORE", "Start refused: no NC core attached");
        return false;
    }
    signals_.set(p + "CADV", 1);
    const bool resuming = active_;
    if (!resuming) setProgramActive(true);
    alarm_.clear();
    prompt_.clear();
    std::string result = resuming ? runner_->resume()
                         : mdi    ? runner_->startMdi()
                                  : runner_->start(selectedProgram_);
    signals_.set(p + "CADV", 0);
    if (resuming && result.empty()) {
        held_ = false;
        signals_.set(p + "SHOLD", 0);
    }
    if (!result.empty()) {
        if (!resuming) setProgramActive(false);
        alarm_ = result;
        return false;
    }
    return true;
}

bool ProcessControl::selectProgram(int number) {
    if (active_) {
        raiseAlarm("ALARM_SELECT_PROGRAM_ACTIVE", "Program selection refused: a program is active");
        return false;
    }
    selectedProgram_ = number;
    return true;
}

void ProcessControl::programFinished(std::string alarm) {
    setProgramActive(false);
    prompt_.clear();
    if (!alarm.empty()) alarm_ = std::move(alarm);
}

void ProcessControl::programStopped(std::string message) {
    held_ = true;
    signals_.set(signalPrefix() + "SHOLD", 1);
    prompt_ = std::move(message);
}

void ProcessControl::setProgramActive(bool active) {
    active_ = active;
    if (!active && held_) {
        held_ = false;
        signals_.set(signalPrefix() + "SHOLD", 0);
    }
    signals_.set(signalPrefix() + "SACTIV", active ? 1 : 0);
}

}  // namespace mtc::core
