#include "cnc_core/compensation/InsertedBlocks.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <set>
#include <utility>

#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/text/Numbers.h"

namespace mtc::core {
namespace {

constexpr std::uint64_t kChunk = 65536;       ///< blocks per interpreter call
constexpr std::size_t kMaxDiagnostics = 100;  ///< kept of a run (the first ones)
constexpr std::size_t kMaxInserted = 100000;  ///< one per block at most; a bound for huge programs

/// "12.5", "-3", "0.1235": up to four decimals, no trailing zeros.
std::string number(double value) {
    if (std::fabs(value) < 0.00005) value = 0.0;
    std::string out = formatFixed(value, 4);
    while (!out.empty() && out.back() == '0')
        out.pop_back();
    if (!out.empty() && out.back() == '.') out.pop_back();
    return out;
}

/// "X12.5", "Z1-42", "Y1 25" (a space after a name that ends in its index digit).
std::string word(const std::string& name, double value) {
    const std::string digits = number(value);
    const bool space = !name.empty() && std::isdigit(static_cast<unsigned char>(name.back())) &&
                       digits.front() != '-';
    return name + (space ? " " : "") + digits;
}

char centreLetter(AxisDefinition definition) {
    switch (definition) {
        case AxisDefinition::X:
            return 'I';
        case AxisDefinition::Y:
            return 'J';
        case AxisDefinition::Z:
            return 'K';
        default:
            return '?';
    }
}

/// Collects the inserted moves of a run, formatted as the program would write them.
class InsertionCollector : public MachineSink {
  public:
    explicit InsertionCollector(InsertedBlocks& out) : out_(out) {}
    void attach(const Interpreter* interpreter) { interpreter_ = interpreter; }

    void motion(const Motion& m) override {
        if (!m.inserted || interpreter_ == nullptr || out_.blocks.size() >= kMaxInserted) return;
        if (!seen_.insert({m.where.program, m.blockIndex}).second) return;  // first pass only
        out_.blocks.push_back({m.where.program, m.blockIndex, text(m)});
    }
    void auxiliary(const AuxOutput&) override {}
    void dwell(const SourceLocation&, double) override {}
    void command(const MachineCommand&) override {}

  private:
    std::string text(const Motion& m) const {
        const bool arc = m.type == MotionType::ArcCW || m.type == MotionType::ArcCCW;
        std::string out = m.type == MotionType::ArcCW    ? "G2"
                          : m.type == MotionType::ArcCCW ? "G3"
                          : m.type == MotionType::Rapid  ? "G0"
                                                         : "G1";
        std::array<double, kMaxAxes> tool = m.end;
        for (std::size_t a = 0; a < kMaxAxes; ++a)
            tool[a] -= m.toolOffset[a];
        const auto end = interpreter_->programView(tool);
        for (int a = 0; a < m.axisCount; ++a)
            if (std::fabs(m.end[static_cast<std::size_t>(a)] -
                          m.start[static_cast<std::size_t>(a)]) > 1e-9)
                out += " " +
                       word(interpreter_->programmedAxisName(a), end[static_cast<std::size_t>(a)]);
        if (!arc || m.planeAxis1 < 0 || m.planeAxis2 < 0) return out;
        std::array<double, kMaxAxes> centre = tool;
        const auto p1 = static_cast<std::size_t>(m.planeAxis1);
        const auto p2 = static_cast<std::size_t>(m.planeAxis2);
        centre[p1] = m.center1 - m.toolOffset[p1];
        centre[p2] = m.center2 - m.toolOffset[p2];
        const auto c = interpreter_->programView(centre);
        const PlaneSelection& plane = interpreter_->state().modal.plane;
        for (std::size_t p : {p1, p2})
            out += std::string(" ") + centreLetter(plane.definitionOf(static_cast<int>(p))) +
                   number(c[p]);
        return out;
    }

    InsertedBlocks& out_;
    const Interpreter* interpreter_ = nullptr;
    std::set<std::pair<int, std::uint32_t>> seen_;
};

}  // namespace

InsertedBlocks insertedBlocks(const ProcessConfig& config, const ProgramStore& programs, int number,
                              std::uint64_t blockBudget, std::shared_ptr<const ToolList> tools,
                              std::shared_ptr<const ZeroOffsetTable> zeroOffsets) {
    InsertedBlocks result;
    InsertionCollector collector(result);
    InterpreterServices services;
    services.tools = std::move(tools);
    services.zeroOffsets = std::move(zeroOffsets);
    Interpreter interpreter(config, programs, collector, services);
    collector.attach(&interpreter);
    interpreter.options().continueAfterError = true;
    if (!interpreter.select(number, 0, &result.diagnostics)) return result;
    std::uint64_t blocks = 0;
    for (;;) {
        const std::uint64_t left = blockBudget - blocks;
        const std::uint64_t slice = std::min(left, kChunk);
        const RunResult run = interpreter.run(slice);
        blocks += run.blocksInterpreted;
        const bool chunkEnd = run.status == RunStatus::BudgetExceeded && slice < left;
        for (const Diagnostic& d : run.diagnostics.items())
            if (result.diagnostics.size() < kMaxDiagnostics &&
                !(chunkEnd && d.code == "BLOCK_BUDGET"))
                result.diagnostics.add(d);
        if ((chunkEnd || run.status == RunStatus::Stopped) && blocks < blockBudget) continue;
        break;
    }
    return result;
}

bool usesRadiusCompensation(const Program& program) {
    for (std::size_t i = 0; i < program.words.size(); ++i) {
        const Word w = program.words[i];
        if (w.kind != WordKind::G) continue;
        if (w.expr >= 0) return true;  // G=<expression> may select it
        if (w.number == 41.0 || w.number == 42.0) return true;
    }
    return false;
}

}  // namespace mtc::core
