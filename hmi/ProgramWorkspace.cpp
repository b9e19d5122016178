#include "hmi/ProgramWorkspace.h"

#include "cnc_core/compiler/GlobalMacroFile.h"
#include "hmi/CellSession.h"
#include "hmi/NcOptionsHolder.h"

namespace mtc::hmi {

using mtc::core::CompileStatus;

namespace {
/// How often the panel looks for finished background compiles.
constexpr int kBackgroundPollMs = 50;
}  // namespace

ProgramWorkspace::ProgramWorkspace(CellSession* session, int slot, QObject* parent)
    : QObject(parent), session_(session), slot_(slot), options_(&session->ncOptions()) {
    compilation().setChangeListener([this](int number) { compilationChanged(number); });
    // D-010: the operator sees a user compiler that came with the folder first.
    compilation().setUserCompilerApproval([this](std::string& refusal) {
        QString reason;
        const bool approved = options_->mayRunUserCompilers(reason);
        refusal = reason.toStdString();
        return approved;
    });
    compilation().loadErrorFiles();
    reportLoadProblems();
    reportOptionProblems();
    connect(options_, &NcOptionsHolder::programsInvalidated, this,
            [this](int slot, const QList<int>& numbers) {
                if (slot == slot_) compilation().invalidate({numbers.begin(), numbers.end()});
            });
    connect(session_, &CellSession::processChanged, this, [this](int changed) {
        if (changed == slot_) watchRuntime();
    });
    // D-019: user compilers run beside the panel; their results are taken here.
    backgroundPoll_.setInterval(kBackgroundPollMs);
    connect(&backgroundPoll_, &QTimer::timeout, this, [this] {
        if (compilation().anyCompiling()) compilation().takeFinished();
    });
    backgroundPoll_.start();
}

ProgramWorkspace::~ProgramWorkspace() {
    compilation().setChangeListener({});
    compilation().setUserCompilerApproval({});
}

mtc::core::ProgramCompilation& ProgramWorkspace::compilation() const {
    return session_->cell().compilation(slot_);
}

void ProgramWorkspace::compilationChanged(int number) {
    if (number == 0) {
        for (const auto& program : session_->programs(slot_))
            showCompilerMessages(program->number);
    } else {
        showCompilerMessages(number);
    }
    emit programChanged(number);
}

void ProgramWorkspace::showCompilerMessages(int number) {
    QVector<ErrorEntry> entries;
    for (const auto& error : compilation().messages(number))
        entries.push_back(entryFromCompilerError(error));
    errors_.setCompilerErrors(number, entries);
}

bool ProgramWorkspace::compilerActive() const {
    return options_->compilerActive();
}

bool ProgramWorkspace::setCompilerActive(bool active, QString& error) {
    // The holder clears the objects of both stations (invalidate()).
    return options_->setCompilerActive(active, error);
}

void ProgramWorkspace::setCompilerActive(bool active) {
    QString ignored;
    setCompilerActive(active, ignored);
}

const std::vector<mtc::core::MacroDefinition>& ProgramWorkspace::globalMacros() const {
    return options_->globalMacros();
}

CompileStatus ProgramWorkspace::status(int number) const {
    return compilation().status(number);
}

std::shared_ptr<const mtc::core::CompileResult> ProgramWorkspace::lastResult(int number) const {
    return compilation().lastResult(number);
}

std::shared_ptr<const mtc::core::CompileResult> ProgramWorkspace::runtimeResult(int number) {
    return compilation().runtimeResult(number);
}

std::shared_ptr<const mtc::core::CompileResult> ProgramWorkspace::running(int number) const {
    return compilation().running(number);
}

VelocityProfile ProgramWorkspace::velocityProfile(int number) const {
    const auto analysis = compilation().lookAhead(number);
    return analysis ? profileFromAnalysis(*analysis) : VelocityProfile{};
}

QString ProgramWorkspace::filePath(int number, const QString& extension) const {
    return QString::fromStdString(compilation().filePath(number, extension.toStdString()));
}

int ProgramWorkspace::sourceLineOf(int number, const QString& block) const {
    return compilation().sourceLineOf(number, block.toStdString());
}

bool ProgramWorkspace::save(int number, const QString& text, QString& error) {
    std::string reason;
    if (!compilation().save(number, text.toStdString(), reason)) {
        error = QString::fromStdString(reason);
        return false;
    }
    session_->announcePrograms(slot_);
    return true;
}

bool ProgramWorkspace::compiling(int number) const {
    return compilation().compiling(number);
}

bool ProgramWorkspace::compile(int number, QString& error) {
    std::string reason;
    if (compilation().compile(number, reason)) return true;
    using Refusal = mtc::core::ProgramCompilation::Refusal;
    switch (compilation().lastRefusal()) {
        case Refusal::NoProgram:
            error = tr("program %1 does not exist").arg(number);
            break;
        case Refusal::CompilerOff:
            error = tr("the compiler is not active (NC options: Compiler active = No)");
            break;
        case Refusal::NothingToCompile:
            error = tr("the program uses no compiler keyword: nothing to compile");
            break;
        case Refusal::UserCompilerBusy:
            error = tr("a user compiler runs: program %1 is compiled when it is done").arg(number);
            break;
        case Refusal::None:
            error = QString::fromStdString(reason);
            break;
    }
    return false;
}

void ProgramWorkspace::reportLoadProblems() {
    for (const mtc::core::Diagnostic& d : session_->loadProblems().items()) {
        ErrorEntry entry;
        entry.warning = d.severity == mtc::core::Severity::Warning;
        entry.program = d.where.program;
        setEntryText(entry, d);
        errors_.add(entry);
    }
}

void ProgramWorkspace::reportOptionProblems() {
    for (const mtc::core::NcOptionsProblem& problem : options_->loadProblems()) {
        ErrorEntry entry;
        entry.code = problem.file == mtc::core::kGlobalMacroFileName ? "GLOBAL_MACRO_REFUSED"
                                                                     : "NC_OPTION_REFUSED";
        entry.line = problem.line;
        entry.message = QString("%1 line %2: %3")
                            .arg(QString::fromStdString(problem.file))
                            .arg(problem.line)
                            .arg(QString::fromStdString(problem.message));
        errors_.add(entry);
    }
}

void ProgramWorkspace::requestEdit(int number, int line) {
    editProgram_ = number;
    editLine_ = line;
}

void ProgramWorkspace::watchRuntime() {
    const mtc::core::DiagnosticLog& log = session_->station(slot_).diagnostics();
    if (log.lastSerial() == seenDiagnostic_) return;
    QVector<ErrorEntry> entries;
    log.forEachAfter(seenDiagnostic_, [&](const mtc::core::LoggedDiagnostic& record) {
        ErrorEntry entry = entryFromDiagnostic(record.diagnostic, originOf(record.source));
        if (record.source == mtc::core::DiagnosticSource::Mdi) {
            entry.program = 0;  // the MDI entry is no program of the store
        } else {
            if (entry.program == 0) entry.program = session_->control(slot_).selectedProgram();
            mapToSource(entry);
        }
        entries.push_back(entry);
    });
    seenDiagnostic_ = log.lastSerial();
    errors_.addAll(entries);
}

void ProgramWorkspace::mapToSource(ErrorEntry& entry) const {
    const auto result = compilation().running(entry.program);
    const int process = session_->processConfig(slot_).index;
    if (!result || !session_->store().findRuntime(process, entry.program)) return;
    // The alarm names the compiled program's block (N0053:0001) and its line
    // in the object text; the line map leads back to the source line.
    const int objectLine = entry.line;
    int sourceLine = 0;
    if (objectLine > 0 && static_cast<std::size_t>(objectLine) <= result->lineMap.size())
        sourceLine = static_cast<int>(result->lineMap[objectLine - 1].sourceLine);
    entry.line = sourceLine;
    entry.details << ProgramWorkspace::tr("compiled program, object line %1; source line %2")
                         .arg(objectLine)
                         .arg(sourceLine > 0 ? QString::number(sourceLine)
                                             : ProgramWorkspace::tr("unknown"));
}

ErrorOrigin originOf(mtc::core::DiagnosticSource source) {
    switch (source) {
        case mtc::core::DiagnosticSource::Run:
            return ErrorOrigin::Runtime;
        case mtc::core::DiagnosticSource::Mdi:
            return ErrorOrigin::Mdi;
        case mtc::core::DiagnosticSource::Restart:
            return ErrorOrigin::Restart;
    }
    return ErrorOrigin::Runtime;
}

ErrorEntry entryFromCompilerError(const mtc::core::CompilerError& error) {
    ErrorEntry entry;
    entry.origin = ErrorOrigin::Compiler;
    entry.warning = error.severity == mtc::core::Severity::Warning;
    entry.program = error.program;
    entry.block = error.block.empty() && error.generalNumber > 0
                      ? QString("A%1").arg(error.generalNumber, 4, 10, QChar('0'))
                      : QString::fromStdString(error.block);
    entry.line = error.sourceLine;
    mtc::core::Diagnostic diagnostic;
    diagnostic.severity = error.severity;
    diagnostic.code = error.code;
    diagnostic.message = error.message;
    diagnostic.details = error.details;
    setEntryText(entry, diagnostic);
    return entry;
}

}  // namespace mtc::hmi
