#include "cnc_core/restart/TargetPath.h"

#include <charconv>
#include <cmath>

#include "cnc_core/interp/ExpressionEvaluator.h"
#include "cnc_core/language/CheckedNumber.h"
#include "cnc_core/restart/RestartRoute.h"
#include "cnc_core/text/Numbers.h"

namespace mtc::core {

namespace {

bool parseNumber(std::string_view text, int& value) {
    if (text.empty() || text.size() > 9) return false;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    return result.ec == std::errc() && result.ptr == text.data() + text.size() && value >= 0;
}

bool parseReference(std::string_view text, PathReference& ref) {
    ref.text = std::string(text);
    if (!text.empty() && (text.front() == 'P' || text.front() == 'p')) {
        const auto colon = text.find(':');
        if (colon == std::string_view::npos || !parseNumber(text.substr(1, colon - 1), ref.program))
            return false;
        text.remove_prefix(colon + 1);
    }
    if (text.size() < 2) return false;
    const char kind = static_cast<char>(text.front() & ~0x20);  // upper case
    if (kind != 'N' && kind != 'L') return false;
    ref.byLine = kind == 'L';
    return parseNumber(text.substr(1), ref.number);
}

/// Follows the references one program level after the other.
class PathFollower {
  public:
    PathFollower(const ProgramStore& store, int process, const InterpreterState* current,
                 TargetPathResult& out)
        : store_(store), process_(process), current_(current), out_(out) {}

    bool follow(const std::vector<PathReference>& refs, int mainProgram) {
        ProgramPtr program = store_.find(process_, mainProgram);
        if (!program)
            return fail("RESTART_PROGRAM_NOT_FOUND", {mainProgram, "", 0, 0},
                        "program " + std::to_string(mainProgram) + " does not exist in process " +
                            std::to_string(process_));
        int calls = 0;
        for (std::size_t i = 0; i < refs.size(); ++i) {
            std::uint32_t block = 0;
            if (!locate(refs[i], program, block)) return false;
            if (i + 1 == refs.size()) {
                out_.selection.target = {program->number, block};
                return true;
            }
            out_.selection.path.push_back({program->number, block});
            if (!onward(*program, block, refs[i + 1], program, calls)) return false;
        }
        return true;
    }

  private:
    bool fail(const char* code, SourceLocation where, std::string message,
              std::vector<std::string> details = {}) {
        out_.diagnostics.error(code, std::move(where), std::move(message), std::move(details));
        return false;
    }

    /// Finds the block `ref` names in `program`.
    bool locate(const PathReference& ref, const ProgramPtr& program, std::uint32_t& block) {
        const SourceLocation here{program->number, "", 0, 0};
        if (ref.program >= 0 && ref.program != program->number)
            return fail("RESTART_PATH_PROGRAM", here,
                        ref.text + ": the path is in program " + std::to_string(program->number) +
                            " here, not in program " + std::to_string(ref.program));
        if (program->isCycle)
            return fail("RESTART_IN_CYCLE", here,
                        "target and start block cannot be selected inside a cycle (seed 000, 2.5)");
        for (std::uint32_t b = 0; b < program->blocks.size(); ++b) {
            const Block& candidate = program->blocks[b];
            if (candidate.flags & kBlockProgramEnd) continue;
            const bool hit =
                ref.byLine ? ref.number >= static_cast<int>(candidate.line) &&
                                 ref.number < static_cast<int>(candidate.line + candidate.lineCount)
                           : candidate.number == ref.number;
            if (!hit) continue;
            block = b;
            return true;
        }
        return fail("RESTART_PATH_BLOCK_NOT_FOUND", here,
                    ref.text + ": program " + std::to_string(program->number) + " has no " +
                        (ref.byLine ? "block on line " : "block N") + std::to_string(ref.number));
    }

    /// The program the jump or call of `block` leads to (`next` may fix a
    /// variable program number).
    bool onward(const Program& program, std::uint32_t block, const PathReference& next,
                ProgramPtr& destination, int& calls) {
        const SourceLocation where = locationOf(program, block);
        const std::optional<Word> word = jumpWordOf(program, block);
        const PathStepKind kind = word ? pathStepKind(word->jump) : PathStepKind::None;
        if (kind == PathStepKind::None)
            return fail("RESTART_PATH_NOT_A_CALL", where,
                        "the path goes on from a block without a jump or call that <Plane+> can "
                        "follow (BRA, BEQ, BNE, BPL, BMI, BES, BER, BSR, BEV, JSR, JEV, JMP, ...)");
        if (kind == PathStepKind::Call && ++calls >= kMaxSearchLevels)
            return fail("RESTART_PATH_DEPTH", where,
                        "the target would lie deeper than program level 10 (seed 000, 2.5)");
        setEvent(program, *word);
        const bool byProgram = word->jump == JumpKind::JSR || word->jump == JumpKind::JEV ||
                               word->jump == JumpKind::JMP;
        return byProgram ? programOf(program, *word, where, next, destination)
                         : labelOf(program, *word, where, destination);
    }

    void setEvent(const Program& program, const Word& word) {
        if (word.jump != JumpKind::BES && word.jump != JumpKind::BER &&
            word.jump != JumpKind::BEV && word.jump != JumpKind::JEV)
            return;
        (void)program;
        const int eventProcess = word.eventProcess < 0 ? process_ : word.eventProcess;
        out_.selection.eventChanges[{eventProcess, word.eventNumber}] = word.jump != JumpKind::BER;
    }

    bool labelOf(const Program& program, const Word& word, const SourceLocation& where,
                 ProgramPtr& destination) {
        const std::string_view label = program.text(word.text);
        ProgramPtr self = store_.find(process_, program.number);
        std::uint32_t block = 0;
        ProgramPtr found;
        if (store_.findLabel(process_, self, label, found, block)) {
            if (found == self || found == store_.library(process_)) {
                destination = found;
                return true;
            }
            std::string cycle;
            for (const auto& entry : store_.cycles())
                if (entry.second == found) cycle = entry.first;
            return fail("RESTART_IN_CYCLE", where,
                        "label ." + std::string(label) + " lies in the cycle " + cycle +
                            ": target and start block cannot be selected inside a cycle");
        }
        return fail("RESTART_PATH_LABEL_NOT_FOUND", where,
                    "label ." + std::string(label) + " is neither in program " +
                        std::to_string(program.number) + " nor in program 99");
    }

    bool programOf(const Program& program, const Word& word, const SourceLocation& where,
                   const PathReference& next, ProgramPtr& destination) {
        double number = word.number;
        const auto literal = exactInteger<long long>(number);
        std::string shown = literal ? std::to_string(*literal) : formatGeneral(number, 10);
        if (word.expr >= 0 && !variableProgram(program, word, where, next, number, shown))
            return false;
        // Any double may come here (@1=-1E308): no cast outside int's range
        // (fuzz finding target_path e0dea8c, replayed under UBSan).
        const std::optional<int> whole = exactInteger<int>(number);
        destination = whole ? store_.find(process_, *whole) : nullptr;
        if (destination) return true;
        return fail("RESTART_PATH_PROGRAM_NOT_FOUND", where,
                    "the command leads to program " + shown + ", which does not exist in process " +
                        std::to_string(process_));
    }

    /// JSR @n / JMP @n / JEV @n: the operator's entry in the variable window
    /// (next reference's P prefix), else the variable's current value.
    bool variableProgram(const Program& program, const Word& word, const SourceLocation& where,
                         const PathReference& next, double& number, std::string& shown) {
        const ExprNode& node = program.expressions[static_cast<std::size_t>(word.expr)];
        const bool single = node.op == ExprOp::Variable &&
                            (node.process < 0 || node.process == process_) && node.index >= 0 &&
                            node.index < kVariableCount;
        if (single && next.program >= 0) {
            out_.selection.variableChanges[node.index] = next.program;
            number = next.program;
            shown = std::to_string(next.program) + " (@" + std::to_string(node.index) + ")";
            return true;
        }
        InterpreterState empty;
        const ExpressionEvaluator evaluator(
            {current_ ? current_ : &empty, nullptr, nullptr, nullptr, process_});
        EvaluationError error;
        if (!evaluator.evaluate(program, word.expr, number, error))
            return fail("RESTART_PATH_PROGRAM_NOT_FOUND", where,
                        "the program number cannot be evaluated: " + error.message);
        // Any double may come out (@1=-1E308): shown as it is, never cast
        // blindly (fuzz finding target_path e0dea8c).
        const auto whole = exactInteger<long long>(number);
        shown = whole ? std::to_string(*whole) : formatGeneral(number, 10);
        if (single) shown += " (the value of @" + std::to_string(node.index) + ")";
        return true;
    }

    const ProgramStore& store_;
    int process_;
    const InterpreterState* current_;
    TargetPathResult& out_;
};

}  // namespace

bool parseTargetPath(std::string_view text, std::vector<PathReference>& references,
                     DiagnosticList& diagnostics) {
    references.clear();
    std::size_t begin = 0;
    while (true) {
        const std::size_t end = text.find('>', begin);
        const std::string_view piece = text.substr(
            begin, end == std::string_view::npos ? std::string_view::npos : end - begin);
        PathReference ref;
        if (!parseReference(piece, ref)) {
            diagnostics.error(
                "RESTART_PATH_SYNTAX", {},
                "bad target path '" + std::string(text) + "' at '" + std::string(piece) + "'",
                {"a path is N<number> or L<line> references, each optionally "
                 "prefixed by P<program>:, separated by '>' (e.g. N0010>P99:N0004)"});
            return false;
        }
        references.push_back(ref);
        if (end == std::string_view::npos) break;
        begin = end + 1;
    }
    if (references.size() <= 4 * static_cast<std::size_t>(kMaxSearchLevels)) return true;
    diagnostics.error("RESTART_PATH_SYNTAX", {}, "the target path has too many references");
    return false;
}

TargetPathResult resolveTargetPath(std::string_view text, const ProgramStore& store, int process,
                                   int mainProgram, const InterpreterState* current) {
    TargetPathResult out;
    out.selection.process = process;
    out.selection.mainProgram = mainProgram;
    std::vector<PathReference> references;
    if (!parseTargetPath(text, references, out.diagnostics)) {
        out.syntaxError = true;
        return out;
    }
    out.ok = PathFollower(store, process, current, out).follow(references, mainProgram);
    return out;
}

}  // namespace mtc::core
