#include "cnc_core/mdi/MdiSession.h"

#include "cnc_core/mdi/MdiEntry.h"

namespace mtc::core {

namespace {

/// The input's lines as the MDI entry counts them (1-based in diagnostics).
std::vector<std::string> inputLines(const std::string& input) {
    std::vector<std::string> lines;
    std::size_t begin = 0;
    while (begin <= input.size()) {
        const std::size_t end = input.find('\n', begin);
        lines.push_back(input.substr(begin, end == std::string::npos ? end : end - begin));
        if (end == std::string::npos) break;
        begin = end + 1;
    }
    return lines;
}

const Diagnostic* firstError(const DiagnosticList& diagnostics) {
    for (const Diagnostic& d : diagnostics.items())
        if (d.severity == Severity::Error) return &d;
    return nullptr;
}

}  // namespace

bool MdiSession::recall(std::size_t row) {
    if (row >= history_.size()) return false;
    input_ = history_[row].text;
    setMessage(
        text("MDI_TEXT_RECALLED", "Entry %1 recalled: Start runs it", {std::to_string(row + 1)}),
        false);
    return true;
}

bool MdiSession::check(const std::vector<MacroDefinition>& globals, DiagnosticList& diagnostics) {
    const MdiEntry entry = prepareMdiEntry(input_, globals);
    if (!entry.runnable()) {
        diagnostics.append(entry.diagnostics);
        reportRefusal(entry.diagnostics);
        return false;
    }
    std::string expanded;
    for (const std::string& line : entry.expanded) {
        const std::size_t first = line.find_first_not_of(" \t");
        const std::size_t last = line.find_last_not_of(" \t");
        if (!expanded.empty()) expanded += " | ";
        if (first != std::string::npos) expanded += line.substr(first, last - first + 1);
    }
    setMessage(text("MDI_TEXT_INPUT_CORRECT", "Input correct: %1", {expanded}), false);
    return true;
}

std::string MdiSession::take(const std::vector<MacroDefinition>& globals, ProgramPtr& program,
                             DiagnosticList& diagnostics) {
    MdiEntry entry = prepareMdiEntry(input_, globals);
    if (!entry.runnable()) {
        diagnostics.append(entry.diagnostics);
        reportRefusal(entry.diagnostics);
        const Diagnostic* error = firstError(entry.diagnostics);
        return error ? formatMdiDiagnostic(*error, language_) : cannotRun();
    }
    program = entry.program;
    running_ = input_;
    history_.push_back({input_, runningOutcome()});
    if (history_.size() > kMaxHistory) history_.pop_front();
    setMessage(text("MDI_TEXT_RUNNING", "Running the MDI entry"), false);
    return {};
}

void MdiSession::ended(bool completed, DiagnosticList& diagnostics) {
    std::string outcome =
        completed ? text("MDI_TEXT_OUTCOME_DONE", "done") : text("MDI_TEXT_OUTCOME_RESET", "reset");
    DiagnosticList annotated;
    for (Diagnostic d : diagnostics.items()) {
        attachInputLine(d, running_);
        annotated.add(std::move(d));
    }
    diagnostics = std::move(annotated);
    if (const Diagnostic* error = firstError(diagnostics)) {
        reportRefusal(diagnostics);
        outcome = text("MDI_TEXT_OUTCOME_ERROR", "error line %1: %2",
                       {std::to_string(error->where.line), messageLine(*error, language_)});
    } else if (completed) {
        setMessage(text("MDI_TEXT_DONE", "MDI entry done"), false);
        if (input_ == running_) input_.clear();  // MDI-004: ready for the next entry
    } else {
        setMessage(text("MDI_TEXT_ABANDONED", "MDI entry abandoned (Control reset)"), true);
    }
    if (!history_.empty() && history_.back().outcome == runningOutcome())
        history_.back().outcome = outcome;
    running_.clear();
}

void MdiSession::attachInputLine(Diagnostic& diagnostic, const std::string& input) {
    const int line = diagnostic.where.line;
    const std::vector<std::string> lines = inputLines(input);
    if (line <= 0 || static_cast<std::size_t>(line) > lines.size()) return;
    const std::string detail = mdiInputDetail(line, lines[static_cast<std::size_t>(line) - 1]);
    for (const std::string& existing : diagnostic.details)
        if (existing == detail) return;
    diagnostic.details.push_back(detail);
}

std::string MdiSession::text(const char* code, const char* english,
                             const std::vector<std::string>& values) const {
    return alarmText(code, english, language_, values);
}

std::string MdiSession::runningOutcome() const {
    return text("MDI_TEXT_OUTCOME_RUNNING", "running");
}

std::string MdiSession::cannotRun() const {
    return text("MDI_TEXT_CANNOT_RUN", "MDI: the input cannot run");
}

void MdiSession::setMessage(std::string text, bool error) {
    message_ = std::move(text);
    messageIsError_ = error;
}

void MdiSession::reportRefusal(const DiagnosticList& diagnostics) {
    const Diagnostic* error = firstError(diagnostics);
    if (!error) return setMessage(cannotRun(), true);
    const std::string text = formatMdiDiagnostic(*error, language_);
    setMessage(text.substr(0, text.find('\n')), true);
}

}  // namespace mtc::core
