#include "hmi/ProgramWorkspace.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>

#include "cnc_core/compiler/CompilerFiles.h"
#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/compiler/GlobalMacroFile.h"
#include "cnc_core/compiler/UserCompilers.h"
#include "cnc_core/compiler/lookahead/LookAheadPass.h"
#include "cnc_core/language/CompilerWords.h"
#include "cnc_core/language/Parser.h"
#include "cnc_core/program/AtomicWrite.h"
#include "hmi/CellSession.h"
#include "hmi/NcOptionsHolder.h"

namespace mtc::hmi {

using mtc::core::CompileStatus;

namespace {

/// The standard passes, with a look-ahead pass that hands its analysis
/// (the velocity profile) to `capture`.
mtc::core::CompilerPassList passesCapturing(
    const std::shared_ptr<mtc::core::lookahead::LookAheadAnalysis>& capture) {
    mtc::core::CompilerPassList passes = mtc::core::standardCompilerPasses();
    for (auto& pass : passes)
        if (pass->name() == "look-ahead")
            pass = std::make_shared<mtc::core::lookahead::LookAheadPass>(
                mtc::core::lookahead::LookAheadDefaults{}, capture);
    return passes;
}

}  // namespace

ProgramWorkspace::ProgramWorkspace(CellSession* session, int slot, QObject* parent)
    : QObject(parent),
      session_(session),
      slot_(slot),
      lookAhead_(std::make_shared<mtc::core::lookahead::LookAheadAnalysis>()),
      compiler_(passesCapturing(lookAhead_)),
      options_(&session->ncOptions()) {
    loadErrorFiles();
    reportLoadProblems();
    reportOptionProblems();
    connect(options_, &NcOptionsHolder::programsInvalidated, this,
            [this](int slot, const QList<int>& numbers) {
                if (slot == slot_) invalidate(numbers);
            });
    connect(session_, &CellSession::processChanged, this, [this](int changed) {
        if (changed == slot_) watchRuntime();
    });
    session_->station(slot_).setPreparer([this](int number, mtc::core::DiagnosticList& diagnostics) {
        return prepareRuntime(number, diagnostics);
    });
}

ProgramWorkspace::~ProgramWorkspace() {
    session_->station(slot_).setPreparer({});
}

std::string ProgramWorkspace::prepareRuntime(int number, mtc::core::DiagnosticList& diagnostics) {
    if (!session_->program(slot_, number)) return {};  // the interpreter reports it
    if (std::string alarm = prepareOne(number, diagnostics); !alarm.empty()) return alarm;
    // Program 99 holds the labels a program calls: it runs compiled as well.
    if (number != 99 && session_->program(slot_, 99)) return prepareOne(99, diagnostics);
    return {};
}

std::string ProgramWorkspace::prepareOne(int number, mtc::core::DiagnosticList& diagnostics) {
    const int process = session_->processConfig(slot_).index;
    mtc::core::ProgramStore& store = session_->mutableStore();
    auto runSource = [&] {
        store.putRuntime(process, number, nullptr);
        running_.remove(number);
    };
    if (!compilerActive()) {
        runSource();
        // Seed 001 ch. 7: with the compiler off, a compiler keyword is an
        // error at download, before any block of the program runs.
        mtc::core::Diagnostic keyword;
        const auto source = session_->program(slot_, number);
        if (source && mtc::core::findCompilerWord(*source, keyword)) {
            diagnostics.add(keyword);
            return mtc::core::formatDiagnostic(keyword);
        }
        return {};
    }
    CompileStatus current = status(number);
    if (current == CompileStatus::NotNeeded) {
        runSource();
        return {};
    }
    if (current == CompileStatus::NotCompiled) {
        QString ignored;  // compile() only refuses cases excluded above
        compile(number, ignored);
        current = status(number);
    }
    const auto result = current == CompileStatus::Compiled ? runtimeResult(number) : nullptr;
    if (!result) {
        runSource();
        return QString("Start refused: program %1 has compiler errors \u2014 see error window")
            .arg(number)
            .toStdString();
    }
    if (running_.value(number) == result && store.findRuntime(process, number)) return {};
    const auto source = session_->program(slot_, number);
    mtc::core::ParseOptions options;
    options.programNumber = number;
    options.name = source->name;
    store.putRuntime(
        process, number,
        std::make_shared<mtc::core::Program>(mtc::core::parseProgram(result->objectText, options)));
    running_[number] = result;
    return {};
}

bool ProgramWorkspace::compilerActive() const {
    return options_->compilerActive();
}

bool ProgramWorkspace::setCompilerActive(bool active, QString& error) {
    // The holder clears the objects of both stations (invalidate()).
    return options_->setCompilerActive(active, error);
}

const std::vector<mtc::core::MacroDefinition>& ProgramWorkspace::globalMacros() const {
    return options_->globalMacros();
}

void ProgramWorkspace::setCompilerActive(bool active) {
    QString ignored;
    setCompilerActive(active, ignored);
}

void ProgramWorkspace::invalidate(const QList<int>& numbers) {
    const int process = session_->processConfig(slot_).index;
    for (int number : numbers) {
        if (running_.contains(number))  // the source runs again
            session_->mutableStore().putRuntime(process, number, nullptr);
        clearObjects(number);
        status_.remove(number);  // no files any more: N
        errors_.setCompilerErrors(number, {});
    }
    needsCompiling_.clear();  // the global macros may have changed
    emit programChanged(0);
}

mtc::core::CompilerOptions ProgramWorkspace::compilerOptions(int number) const {
    mtc::core::CompilerOptions options;
    options.compilerActive = compilerActive();
    options.process = &session_->processConfig(slot_);
    options.programNumber = number;
    options.globalMacros = options_->globalMacros();
    if (auto program = session_->program(slot_, number)) options.programName = program->name;
    return options;
}

void ProgramWorkspace::reportLoadProblems() {
    for (const mtc::core::Diagnostic& d : session_->loadProblems().items()) {
        ErrorEntry entry;
        entry.warning = d.severity == mtc::core::Severity::Warning;
        entry.program = d.where.program;
        entry.code = QString::fromStdString(d.code);
        entry.message = QString::fromStdString(d.message);
        for (const std::string& detail : d.details)
            entry.details << QString::fromStdString(detail);
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

mtc::core::CompileResult ProgramWorkspace::runCompilers(
    const mtc::core::Program& program, const mtc::core::CompilerOptions& options) const {
    const mtc::core::UserCompilerSlots& chain = options_->userCompilers();
    if (chain.empty()) return compiler_.compile(program, options);
    // D-010: a command that came with the program folder runs only when the
    // operator has seen and approved it.
    QString refusal;
    if (!options_->mayRunUserCompilers(refusal)) {
        mtc::core::CompileResult refused;
        refused.status = CompileStatus::Error;
        mtc::core::CompilerError error;
        error.code = "USER_COMPILER_NOT_APPROVED";
        error.program = options.programNumber;
        error.generalNumber = 1;
        error.details = {refusal.toStdString()};
        error.message = "User compiler not approved: not run.";
        refused.errors.push_back(std::move(error));
        return refused;
    }
    // C-011: the user compilers exchange files in the program directory (a
    // temporary one for the built-in programs).
    QString directory = session_->programDirectory();
    QTemporaryDir scratch;
    if (directory.isEmpty()) directory = scratch.path();
    return mtc::core::compileWithUserCompilers(compiler_, program.source, options, chain,
                                               directory.toStdString());
}

bool ProgramWorkspace::needsCompiling(int number, const mtc::core::ProgramPtr& program) const {
    if (program->usesCompilerKeywords) return true;
    // Seed 001 ch. 8: a user compiler runs even without INDRAMAT keywords.
    if (!options_->userCompilers().empty()) return true;
    if (options_->globalMacros().empty()) return false;
    // With global macros every block text is searched: once per program version.
    NeedsCompiling& known = needsCompiling_[number];
    const auto same = known.program.lock();
    if (same != program) {
        mtc::core::CompilerOptions options = compilerOptions(number);
        options.compilerActive = true;  // the bit says whether it needs compiling
        known = {program, mtc::core::needsCompilation(*program, options)};
    }
    return known.needed;
}

CompileStatus ProgramWorkspace::status(int number) const {
    const auto program = session_->program(slot_, number);
    if (!program) return CompileStatus::NotNeeded;
    if (!needsCompiling(number, program)) return CompileStatus::NotNeeded;
    if (status_.contains(number)) return status_.value(number);
    return statusFromFiles(number);
}

std::shared_ptr<const mtc::core::CompileResult> ProgramWorkspace::lastResult(int number) const {
    return results_.value(number);
}

std::shared_ptr<const mtc::core::CompileResult> ProgramWorkspace::runtimeResult(int number) {
    if (auto result = results_.value(number)) return result;
    const auto program = session_->program(slot_, number);
    if (!program || status(number) != CompileStatus::Compiled) return nullptr;
    mtc::core::CompilerOptions options = compilerOptions(number);
    options.compilerActive = true;
    *lookAhead_ = {};
    auto result = std::make_shared<mtc::core::CompileResult>(runCompilers(*program, options));
    if (result->status != CompileStatus::Compiled) return nullptr;
    profiles_[number] = profileFromAnalysis(*lookAhead_);
    results_[number] = result;
    showCompilerMessages(number, *result);  // the warnings are in no file (C-014)
    return result;
}

QString ProgramWorkspace::filePath(int number, const QString& extension) const {
    const QString directory = session_->programDirectory();
    const auto program = session_->program(slot_, number);
    if (directory.isEmpty() || !program) return {};
    const QString dat = QDir(directory).filePath(QString::fromStdString(program->name));
    if (!QFileInfo::exists(dat)) return {};
    const QFileInfo info(dat);
    return info.dir().filePath(info.completeBaseName() + "." + extension);
}

CompileStatus ProgramWorkspace::statusFromFiles(int number) const {
    const QString dat = filePath(number, "DAT");
    if (dat.isEmpty()) return CompileStatus::NotCompiled;
    const QDateTime source = QFileInfo(dat).lastModified();
    // CF-013: an object file is never beside the errors of another compile,
    // so a current .NCO means compiled.
    const QFileInfo object(filePath(number, "NCO"));
    if (object.exists() && object.lastModified() >= source) return CompileStatus::Compiled;
    const QFileInfo error(filePath(number, "ERR"));
    if (error.exists() && error.lastModified() >= source) {
        // C-014: only errors make status E (an .ERR with notices only, as
        // older versions wrote beside a good .NCO, does not)
        QFile file(error.filePath());
        if (!file.open(QIODevice::ReadOnly) ||
            mtc::core::errorFileHasErrors(file.readAll().toStdString()))
            return CompileStatus::Error;
    }
    return CompileStatus::NotCompiled;
}

void ProgramWorkspace::setStatus(int number, CompileStatus status) {
    status_[number] = status;
    emit programChanged(number);
}

void ProgramWorkspace::clearObjects(int number) {
    for (const QString& extension : {QString("NCO"), QString("ERR")}) {
        const QString path = filePath(number, extension);
        if (!path.isEmpty()) QFile::remove(path);
    }
    results_.remove(number);
    profiles_.remove(number);
    running_.remove(number);  // the store dropped its runtime version with the new source
}

bool ProgramWorkspace::save(int number, const QString& text, QString& error) {
    const auto old = session_->program(slot_, number);
    if (!old) {
        error = QString("program %1 does not exist").arg(number);
        return false;
    }
    const std::string bytes = text.toStdString();
    const QString path = filePath(number, "DAT");
    std::string reason;
    if (!path.isEmpty() && !mtc::core::writeFileAtomically(path.toStdString(), bytes, reason)) {
        error = QString("%1 not saved: %2").arg(path, QString::fromStdString(reason));
        return false;
    }
    session_->addProgram(slot_, number, old->name, bytes);
    clearObjects(number);
    errors_.setCompilerErrors(number, {});
    setStatus(number, CompileStatus::NotCompiled);
    return true;
}

bool ProgramWorkspace::compile(int number, QString& error) {
    const auto program = session_->program(slot_, number);
    if (!program) {
        error = QString("program %1 does not exist").arg(number);
        return false;
    }
    if (!compilerActive()) {
        error = "the compiler is not active (NC options: Compiler active = No)";
        return false;
    }
    const mtc::core::CompilerOptions options = compilerOptions(number);
    if (!mtc::core::needsCompilation(*program, options) && options_->userCompilers().empty()) {
        error = "the program uses no compiler keyword: nothing to compile";
        return false;
    }
    *lookAhead_ = {};
    auto result = std::make_shared<mtc::core::CompileResult>(runCompilers(*program, options));
    profiles_[number] = profileFromAnalysis(*lookAhead_);
    showCompilerMessages(number, *result);
    writeCompileFiles(number, *result);
    results_[number] = result;
    setStatus(number, result->status == CompileStatus::Compiled ? CompileStatus::Compiled
                                                                : CompileStatus::Error);
    return true;
}

void ProgramWorkspace::writeCompileFiles(int number, const mtc::core::CompileResult& result) {
    const QString source = filePath(number, "DAT");
    if (source.isEmpty()) return;  // a program without file (built-in demo)
    std::string errorPath;
    std::string reason;
    if (mtc::core::writeCompileFiles(source.toStdString(), "", result, errorPath, reason)) return;
    ErrorEntry entry;
    entry.program = number;
    entry.code = "FILE_WRITE";
    entry.message = "Compile files not written";
    entry.details << QString::fromStdString(reason);
    errors_.add(entry);
}

int ProgramWorkspace::sourceLineOf(int number, const QString& block) const {
    const auto program = session_->program(slot_, number);
    if (!program || block.isEmpty()) return 0;
    const std::string id = block.toStdString();
    const std::string& text = program->source;
    int line = 1;
    for (std::size_t start = 0; start < text.size(); ++line) {
        std::size_t at = text.find_first_not_of(" /:", start);
        if (at != std::string::npos && text.compare(at, id.size(), id) == 0) {
            const std::size_t after = at + id.size();
            if (after >= text.size() || text[after] == ' ' || text[after] == '\n' ||
                text[after] == '\r' || text[after] == ';')
                return line;
        }
        const std::size_t end = text.find('\n', start);
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return 0;
}

void ProgramWorkspace::loadErrorFiles() {
    for (const auto& program : session_->programs(slot_)) {
        if (status(program->number) != CompileStatus::Error) continue;
        QFile file(filePath(program->number, "ERR"));
        if (!file.open(QIODevice::ReadOnly)) continue;
        std::string identification;
        QVector<ErrorEntry> entries;
        for (const auto& error :
             mtc::core::parseErrorFile(file.readAll().toStdString(), identification)) {
            ErrorEntry entry = entryFromCompilerError(error);
            if (entry.line == 0) entry.line = sourceLineOf(program->number, entry.block);
            entries.push_back(entry);
        }
        errors_.setCompilerErrors(program->number, entries);
    }
}

void ProgramWorkspace::showCompilerMessages(int number, const mtc::core::CompileResult& result) {
    QVector<ErrorEntry> entries;
    for (const auto& e : result.errors)
        entries.push_back(entryFromCompilerError(e));
    errors_.setCompilerErrors(number, entries);
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
    const auto result = running_.value(entry.program);
    const int process = session_->processConfig(slot_).index;
    if (!result || !session_->store().findRuntime(process, entry.program)) return;
    // The alarm names the compiled program's block (N0053:0001) and its line
    // in the object text; the line map leads back to the source line.
    const int objectLine = entry.line;
    int sourceLine = 0;
    if (objectLine > 0 && static_cast<std::size_t>(objectLine) <= result->lineMap.size())
        sourceLine = static_cast<int>(result->lineMap[objectLine - 1].sourceLine);
    entry.line = sourceLine;
    entry.details << QString("compiled program, object line %1; source line %2")
                         .arg(objectLine)
                         .arg(sourceLine > 0 ? QString::number(sourceLine) : QString("unknown"));
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
    entry.code = QString::fromStdString(error.code);
    entry.message = QString::fromStdString(error.message);
    for (const auto& line : error.details)
        entry.details << QString::fromStdString(line);
    return entry;
}

}  // namespace mtc::hmi
