#pragma once

// A station for restart-sequence tests: one station of the core's cell (its
// control keys, simulated SPS and RestartSequence), plus a main program and a
// program 99 with ADJUST / REPOS used by several test files.
#include <string>
#include <vector>

#include "RestartTestSupport.h"
#include "cnc_core/cell/Cell.h"
#include "cnc_core/machine_data/MachineDataStore.h"
#include "cnc_core/restart/RestartSequence.h"

namespace mtc::test {

using core::ControlKey;
using core::DiagnosticList;
using core::OperatingMode;
using core::RestartPhase;
using core::RestartSelection;
using core::SignalChange;

inline const char* kMain =
    "N0001 : T4 S2000 M3 M108\n"
    "N0002 G0 G54 X10 Y10 Z5\n"
    "N0003 G1 Z-2 F300\n"
    "N0004 X50 ;target\n"
    "N0005 M30\n";

inline const char* kLibrary =
    "N0000 M30\n"
    "N0001 .ADJUST @150=M(2) @151=M(5)\n"
    "N0002 G53 G0 Z90 ;clear height\n"
    "N0003 Q9500 ;manual mode\n"
    "N0004 .REPOS G77 S0 M=@150\n"
    "N0005 M=@151\n"
    "N0006 G77 X0 Y0 F2000\n"
    "N0007 G77 Z0 F1000 RTS\n";

/// The core's cell with the restart programs of one process, under the
/// names the restart tests use: its store, the station's interpreter (`live`),
/// the machine data, and a recording of everything the station sends to its
/// machine (`sps`: moves, aux functions; Station::setOutputListener).
struct StationCell : ProcessPrograms<StationCell> {
    explicit StationCell(int process)
        : cell(demoCell()),
          station(cell.station(cell.slotOfProcess(process))),
          config(station.config()),
          store(cell.store()),
          machineData(cell.sharedMachineData()),
          live(station.interpreter()) {
        station.setOutputListener(&sps);
    }
    ~StationCell() { station.setOutputListener(nullptr); }


    core::Cell cell;
    core::Station& station;
    const core::ProcessConfig& config;
    core::ProgramStore& store;
    std::shared_ptr<core::MachineDataStore> machineData;
    core::Interpreter& live;
    core::RecordingSink sps;
};

/// One station of the core's cell with its control keys, SPS and restart
/// sequence (the same wiring as the panel and the CLI: core::Station).
struct RestartStation {
    explicit RestartStation(int process)
        : cell(process),
          control(cell.station.control()),
          sps(cell.station.sps()),
          sequence(cell.station.restartSequence()) {}

    int signal(const std::string& name) const {
        return control.signalTable().get(control.signalPrefix() + name);
    }
    /// Signal changes since the constructor, "NAME=value".
    std::vector<std::string> log() const {
        std::vector<std::string> out;
        for (const SignalChange& c : control.signalTable().log())
            out.push_back(c.name + "=" + std::to_string(c.value));
        return out;
    }
    bool accept(const RestartSelection& s) {
        DiagnosticList d;
        const bool ok = sequence.accept(s, d, 100'000);
        EXPECT_FALSE(d.hasErrors()) << diagnosticsText(d);
        return ok;
    }
    /// Program 99 with ADJUST/REPOS (kLibrary) and main program 1 (kMain).
    void addDemoPrograms() {
        cell.add(kLibrary, 99);
        cell.add(kMain, 1);
    }
    /// Restart of program 1 at block 4: accepted, computing process run.
    RestartPhase restartAtDemoTarget() {
        EXPECT_TRUE(accept(cell.selection(1, 1, 4)));
        return runUntilWaiting();
    }
    /// restartAtDemoTarget(), then Start: ADJUST runs up to its Q9500.
    RestartPhase adjustUntilManualMode() {
        restartAtDemoTarget();
        EXPECT_TRUE(control.press(core::ControlKey::Start));
        return runUntilWaiting();
    }
    RestartPhase runUntilWaiting() {
        for (int i = 0; i < 100; ++i) {
            const RestartPhase p = sequence.advance(100'000);
            if (sequence.held() || (p != RestartPhase::Computing && p != RestartPhase::Adjusting &&
                                    p != RestartPhase::Repositioning && p != RestartPhase::Active))
                return p;
        }
        ADD_FAILURE() << "the sequence does not come to rest";
        return sequence.phase();
    }
    /// Every signal of the restart is 0 (abort / failure left nothing half-switched).
    void expectAllRestartSignalsOff() const {
        for (const char* name :
             {"SBPACT", "CBPSTR", "SREPOS", "CREPOS", "SCREST", "SHOLD", "SACTIV", "CADV"})
            EXPECT_EQ(signal(name), 0) << name;
        EXPECT_EQ(signal("SAUTO") + signal("SMANU"), 1) << "exactly one operating mode";
        EXPECT_EQ(control.keyHandler(), nullptr);
        EXPECT_FALSE(sequence.active());
    }

    StationCell cell;
    core::ProcessControl& control;
    core::SimulatedSps& sps;
    core::RestartSequence& sequence;
};

}  // namespace mtc::test
