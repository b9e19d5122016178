#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "cnc_core/cell/ProgramCompilation.h"
#include "cnc_core/cell/Station.h"
#include "cnc_core/compiler/NcOptions.h"
#include "cnc_core/interp/VariableAccess.h"
#include "cnc_core/language/Parser.h"
#include "cnc_core/machine/AxisTransfer.h"
#include "cnc_core/machine/EventTable.h"
#include "cnc_core/machine/MachineConfig.h"
#include "cnc_core/program/ProgramStore.h"
#include "cnc_core/tooldata/SetupData.h"

namespace mtc::core {

class MachineDataStore;

/// The whole simulated CNC: the machine configuration, the program memory,
/// the machine data, ONE event table, the GAX / FAX axis transfer, the
/// variables every process reaches with @p:n, the NC options, and one
/// Station per process. Plain C++: the panel, the CLI and the tests build
/// the same cell and drive it with advance() and the stations' keys.
class Cell {
  public:
    explicit Cell(MachineConfig config);
    ~Cell();
    Cell(const Cell&) = delete;
    Cell& operator=(const Cell&) = delete;

    const MachineConfig& config() const { return config_; }
    int stationCount() const { return static_cast<int>(stations_.size()); }
    /// Station by slot 0..stationCount()-1 (the order of the configuration).
    Station& station(int slot) { return *stations_.at(static_cast<std::size_t>(slot)); }
    const Station& station(int slot) const { return *stations_.at(static_cast<std::size_t>(slot)); }
    /// The compile status and runtime programs of station `slot`; the
    /// station's Start prepares its program through it.
    ProgramCompilation& compilation(int slot) {
        return *compilations_.at(static_cast<std::size_t>(slot));
    }
    const ProgramCompilation& compilation(int slot) const {
        return *compilations_.at(static_cast<std::size_t>(slot));
    }
    /// Slot of process number `process`, or -1.
    int slotOfProcess(int process) const;

    ProgramStore& store() { return store_; }
    const ProgramStore& store() const { return store_; }
    MachineDataStore& machineData() { return *machineData_; }
    const std::shared_ptr<MachineDataStore>& sharedMachineData() const { return machineData_; }
    EventTable& events() { return *events_; }
    AxisTransfer& axisTransfer() { return axisTransfer_; }
    /// @p:n of every process (the interpreters' variables).
    VariableAccess& variables() { return variables_; }
    /// Tool lists and zero offsets of every process (first the
    /// configuration's); the interpreters read them, a load() is seen by the
    /// next block.
    SetupData& setupData() { return setupData_; }
    const SetupData& setupData() const { return setupData_; }

    /// The folder the programs' files are in ("" = built-in programs, no
    /// files): the compiler writes .NCO / .ERR beside them.
    const std::string& programDirectory() const { return programDirectory_; }
    void setProgramDirectory(std::string directory) { programDirectory_ = std::move(directory); }

    /// The language of the alarms and messages the cell builds from a
    /// diagnostic: English (the CLI's texts) unless the panel passes its own
    /// (docs/DECISIONS.md D-024). Sets it for every station.
    void setLanguage(Language language);
    Language language() const { return language_; }

    /// The NC options (compiler active, user compilers, global macros).
    const NcOptions& ncOptions() const { return ncOptions_; }
    /// Takes new NC options; when the global macro names change, the
    /// programs that name an old or a new macro are parsed again.
    void setNcOptions(NcOptions options);
    /// How program `number` named `name` is parsed: knowing the global macro
    /// names, exactly as the CLI parses it.
    ParseOptions parseOptions(int number, const std::string& name) const;
    /// Names of the global macros (the parser's ParseOptions::macroNames).
    std::vector<std::string> macroNames() const;

    /// Parses `text` and stores it as program `number` of station `slot`.
    ProgramPtr addProgram(int slot, int number, const std::string& name, std::string text);
    /// Stores an already parsed program.
    void putProgram(int slot, int number, ProgramPtr program);
    /// Programs of a station ordered by number.
    std::vector<ProgramPtr> programs(int slot) const;
    /// The source of program `number` of station `slot` (nullptr = none).
    ProgramPtr program(int slot, int number) const;

    /// Moves every station on by `seconds` of simulated time (at most
    /// `maxBlocks` interpreted blocks each).
    void advance(double seconds, std::uint64_t maxBlocks = kBlocksPerAdvance);

  private:
    /// @p:n: the variables of the process's interpreter.
    class Variables : public VariableAccess {
      public:
        explicit Variables(Cell& cell) : cell_(cell) {}
        bool read(int process, int index, double& value) const override;
        bool write(int process, int index, double value) override;

      private:
        Cell& cell_;
    };
    void reparseNaming(const std::vector<std::string>& names);

    MachineConfig config_;
    ProgramStore store_;
    std::shared_ptr<MachineDataStore> machineData_;
    std::shared_ptr<EventTable> events_;
    SetupData setupData_;
    AxisTransfer axisTransfer_;
    Variables variables_;
    NcOptions ncOptions_;
    std::string programDirectory_;
    Language language_ = Language::English;
    std::vector<std::unique_ptr<Station>> stations_;
    std::vector<std::unique_ptr<ProgramCompilation>> compilations_;
};

}  // namespace mtc::core
