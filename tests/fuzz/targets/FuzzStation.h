#pragma once

#include <memory>
#include <string_view>

#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/interp/MachineSink.h"
#include "cnc_core/program/ProgramStore.h"

namespace mtc::fuzz {

/// A sink that requires what leaves the interpreter to be finite: positions,
/// centres, feeds, dwell times, aux values. `input` is the fuzz input (for
/// the message); it must outlive the sink.
class FiniteSink : public core::MachineSink {
  public:
    explicit FiniteSink(std::string_view input) : input_(input) {}
    void motion(const core::Motion& m) override;
    void auxiliary(const core::AuxOutput& a) override;
    void dwell(const core::SourceLocation& where, double seconds) override;
    void command(const core::MachineCommand&) override {}

  private:
    std::string_view input_;
};

/// One process with a program store, a FiniteSink, an interpreter with its
/// own machine data and an adaptive feed control, like a station's.
struct FuzzStation {
    FuzzStation(const core::ProcessConfig& process, std::string_view input);

    core::ProgramStore store;
    FiniteSink sink;
    std::unique_ptr<core::Interpreter> interpreter;
    std::shared_ptr<core::AdaptiveFeedControl> afc;
};

}  // namespace mtc::fuzz
