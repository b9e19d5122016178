#include "cnc_core/restart/SimulatedSps.h"

#include <string>

namespace mtc::core {

namespace {

constexpr int kManualModeRequest = 9500;
constexpr int kAutomaticModeRequest = 9501;

}  // namespace

int SimulatedSps::get(const char* name) const {
    return control_.signalTable().get(control_.signalPrefix() + name);
}

void SimulatedSps::set(const char* name, int value) {
    control_.signalTable().set(control_.signalPrefix() + name, value);
}

void SimulatedSps::cycle() {
    const bool restartActive = get("SBPACT") == 1;
    if (automaticStart_ || !restartActive) set("CBPSTR", restartActive ? 1 : 0);
    const bool retracePossible = get("SREPOS") == 1;
    if (retracePossible && !retraceWasPossible_) reposAfterRestart_ = true;
    retraceWasPossible_ = retracePossible;
    const bool allowed = retracePossible && get("SCREST") == 0;
    const bool requested =
        reposAfterRestart_ || get("CREPOS") == 1 || control_.signalTable().get("mREPOS") == 1;
    set("CREPOS", allowed && requested ? 1 : 0);
    if (get("CREPOS") == 1 || !retracePossible) reposAfterRestart_ = false;
}

bool SimulatedSps::startComputing() {
    if (get("SBPACT") != 1) return false;
    set("CBPSTR", 1);
    return true;
}

void SimulatedSps::auxiliary(const AuxOutput& output) {
    if (output.type != 'Q') return;
    const int q = static_cast<int>(output.value);
    if (q == kManualModeRequest) requestMode(OperatingMode::Manual);
    if (q == kAutomaticModeRequest) requestMode(OperatingMode::Automatic);
}

}  // namespace mtc::core
