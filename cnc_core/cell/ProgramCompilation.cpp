#include "cnc_core/cell/ProgramCompilation.h"

#include <condition_variable>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <system_error>
#include <thread>

#include "cnc_core/cell/Cell.h"
#include "cnc_core/compiler/CompilerFiles.h"
#include "cnc_core/compiler/UserCompilers.h"
#include "cnc_core/compiler/lookahead/LookAheadPass.h"
#include "cnc_core/language/CompilerWords.h"
#include "cnc_core/program/AtomicWrite.h"
#include "cnc_core/program/FileText.h"

namespace mtc::core {

namespace fs = std::filesystem;

namespace {

/// The standard passes, with a look-ahead pass that hands its analysis
/// (the velocity profile) to `capture`.
CompilerPassList passesCapturing(const std::shared_ptr<lookahead::LookAheadAnalysis>& capture) {
    CompilerPassList passes = standardCompilerPasses();
    for (auto& pass : passes)
        if (pass->name() == "look-ahead")
            pass =
                std::make_shared<lookahead::LookAheadPass>(lookahead::LookAheadDefaults{}, capture);
    return passes;
}

/// The modification time of `path`; false when it is not there.
bool modified(const std::string& path, fs::file_time_type& time) {
    std::error_code error;
    time = fs::last_write_time(path, error);
    return !error;
}

/// A private scratch directory for user compilers of built-in programs
/// (C-011: they exchange files in the program directory); removed with it.
class ScratchDirectory {
  public:
    ScratchDirectory() {
        std::string pattern = (fs::temp_directory_path() / "mtc200-compile-XXXXXX").string();
        if (mkdtemp(pattern.data())) path_ = pattern;
    }
    ~ScratchDirectory() {
        std::error_code ignored;
        if (!path_.empty()) fs::remove_all(path_, ignored);
    }
    ScratchDirectory(const ScratchDirectory&) = delete;
    ScratchDirectory& operator=(const ScratchDirectory&) = delete;
    const std::string& path() const { return path_; }

  private:
    std::string path_;
};

CompilerError refusalOf(int number, std::string code, std::string message, std::string detail) {
    CompilerError error;
    error.code = std::move(code);
    error.program = number;
    error.generalNumber = 1;
    error.message = std::move(message);
    error.details = {std::move(detail)};
    return error;
}

}  // namespace

/// A user compiler chain running on its own thread. The thread owns copies
/// of everything it reads (source, options, the process configuration), so
/// neither the cell nor this object has to outlive it.
struct ProgramCompilation::Background {
    std::weak_ptr<const Program> program;  ///< the source it compiles
    std::uint64_t generation = 0;          ///< NC options invalidations when started
    bool keepFiles = true;                 ///< false: in memory (status C from files)
    std::mutex mutex;
    std::condition_variable finished;
    bool done = false;
    std::shared_ptr<const CompileResult> result;
    std::shared_ptr<const lookahead::LookAheadAnalysis> plan;
};

ProgramCompilation::ProgramCompilation(Cell& cell, int slot)
    : cell_(cell),
      slot_(slot),
      capture_(std::make_shared<lookahead::LookAheadAnalysis>()),
      compiler_(passesCapturing(capture_)) {}

ProgramCompilation::~ProgramCompilation() = default;

int ProgramCompilation::process() const {
    return cell_.station(slot_).process();
}

void ProgramCompilation::changed(int number) const {
    if (listener_) listener_(number);
}

CompilerOptions ProgramCompilation::compilerOptions(int number) const {
    CompilerOptions options;
    options.compilerActive = cell_.ncOptions().compilerActive;
    options.process = &cell_.station(slot_).config();
    options.programNumber = number;
    options.globalMacros = cell_.ncOptions().globalMacros;
    if (auto program = cell_.program(slot_, number)) options.programName = program->name;
    return options;
}

bool ProgramCompilation::needsCompiling(int number, const ProgramPtr& program) const {
    if (program->usesCompilerKeywords) return true;
    // Seed 001 ch. 8: a user compiler runs even without INDRAMAT keywords.
    if (!cell_.ncOptions().userCompilers.empty()) return true;
    if (cell_.ncOptions().globalMacros.empty()) return false;
    // With global macros every block text is searched: once per program version.
    NeedsCompiling& known = needsCompiling_[number];
    if (known.program.lock() != program) {
        CompilerOptions options = compilerOptions(number);
        options.compilerActive = true;  // the bit says whether it needs compiling
        known = {program, needsCompilation(*program, options)};
    }
    return known.needed;
}

CompileStatus ProgramCompilation::status(int number) const {
    const auto program = cell_.program(slot_, number);
    if (!program || !needsCompiling(number, program)) return CompileStatus::NotNeeded;
    if (auto known = status_.find(number); known != status_.end()) return known->second;
    return statusFromFiles(number);
}

std::shared_ptr<const CompileResult> ProgramCompilation::lastResult(int number) const {
    auto found = results_.find(number);
    return found == results_.end() ? nullptr : found->second;
}

std::shared_ptr<const CompileResult> ProgramCompilation::running(int number) const {
    auto found = running_.find(number);
    return found == running_.end() ? nullptr : found->second;
}

std::shared_ptr<const lookahead::LookAheadAnalysis> ProgramCompilation::lookAhead(
    int number) const {
    auto found = lookAhead_.find(number);
    return found == lookAhead_.end() ? nullptr : found->second;
}

const std::vector<CompilerError>& ProgramCompilation::messages(int number) const {
    static const std::vector<CompilerError> none;
    auto found = messages_.find(number);
    return found == messages_.end() ? none : found->second;
}

std::shared_ptr<const CompileResult> ProgramCompilation::runtimeResult(int number) {
    if (auto result = lastResult(number)) return result;
    const auto program = cell_.program(slot_, number);
    if (!program || status(number) != CompileStatus::Compiled) return nullptr;
    if (userCompilerBusy()) return nullptr;
    CompilerOptions options = compilerOptions(number);
    options.compilerActive = true;
    if (!cell_.ncOptions().userCompilers.empty()) {
        if (!refusedUserCompilers(number)) startBackground(number, program, options, false);
        return nullptr;
    }
    auto result = std::make_shared<CompileResult>(compileNow(number, *program, options));
    if (result->status != CompileStatus::Compiled) return nullptr;
    results_[number] = result;
    setMessages(number, result->errors);  // the warnings are in no file (C-014)
    return result;
}

CompileResult ProgramCompilation::compileNow(int number, const Program& program,
                                             const CompilerOptions& options) {
    *capture_ = {};
    CompileResult result = compiler_.compile(program, options);
    lookAhead_[number] = std::make_shared<const lookahead::LookAheadAnalysis>(*capture_);
    return result;
}

bool ProgramCompilation::refusedUserCompilers(int number) {
    // D-010: a command that came with the program folder runs only when the
    // operator has seen and approved it.
    std::string refusal;
    if (!approval_ || approval_(refusal)) return false;
    auto refused = std::make_shared<CompileResult>();
    refused->status = CompileStatus::Error;
    refused->errors.push_back(refusalOf(number, "USER_COMPILER_NOT_APPROVED",
                                        "User compiler not approved: not run.", refusal));
    apply(number, refused, nullptr, true);
    return true;
}

void ProgramCompilation::startBackground(int number, const ProgramPtr& program,
                                         const CompilerOptions& options, bool keepFiles) {
    auto job = std::make_shared<Background>();
    job->program = program;
    job->generation = generation_;
    job->keepFiles = keepFiles;
    background_[number] = job;
    auto process = std::make_shared<const ProcessConfig>(*options.process);
    CompilerOptions own = options;
    own.process = process.get();
    std::thread([job, process, own, source = program->source,
                 chain = cell_.ncOptions().userCompilers, directory = cell_.programDirectory()] {
        auto capture = std::make_shared<lookahead::LookAheadAnalysis>();
        const Compiler compiler(passesCapturing(capture));
        ScratchDirectory scratch;  // C-011: built-in programs have no directory
        auto result = std::make_shared<const CompileResult>(compileWithUserCompilers(
            compiler, source, own, chain, directory.empty() ? scratch.path() : directory));
        const std::lock_guard<std::mutex> lock(job->mutex);
        job->result = std::move(result);
        job->plan = std::move(capture);
        job->done = true;
        job->finished.notify_all();
    }).detach();
}

bool ProgramCompilation::userCompilerBusy() const {
    // The user compilers of both stations exchange files of fixed names in
    // the one program directory (C-011): one chain at a time in the cell.
    for (int slot = 0; slot < cell_.stationCount(); ++slot)
        if (cell_.compilation(slot).anyCompiling()) return true;
    return false;
}

bool ProgramCompilation::takeFinished() {
    bool any = false;
    for (auto it = background_.begin(); it != background_.end();) {
        const std::shared_ptr<Background> job = it->second;
        std::unique_lock<std::mutex> lock(job->mutex);
        if (!job->done) {
            ++it;
            continue;
        }
        lock.unlock();
        const int number = it->first;
        it = background_.erase(it);
        any = true;
        // A source saved or NC options changed meanwhile: the result is stale.
        if (job->program.lock() != cell_.program(slot_, number) || job->generation != generation_) {
            changed(number);
            continue;
        }
        if (job->keepFiles)
            apply(number, job->result, job->plan, true);
        else if (job->result->status == CompileStatus::Compiled)
            apply(number, job->result, job->plan, false);
        else
            changed(number);
    }
    return any;
}

void ProgramCompilation::waitForCompiles() {
    for (const auto& entry : background_) {  // (no structured binding: clang's C++17 lambdas)
        Background& job = *entry.second;
        std::unique_lock<std::mutex> lock(job.mutex);
        job.finished.wait(lock, [&job] { return job.done; });
    }
    takeFinished();
}

void ProgramCompilation::apply(int number, std::shared_ptr<const CompileResult> result,
                               std::shared_ptr<const lookahead::LookAheadAnalysis> plan,
                               bool keepFiles) {
    results_[number] = result;
    lookAhead_[number] = std::move(plan);
    messages_[number] = result->errors;
    if (!keepFiles) {  // a compile in memory: files and status stay (C-014)
        changed(number);
        return;
    }
    writeCompileFiles(number, *result);
    setStatus(number, result->status == CompileStatus::Compiled ? CompileStatus::Compiled
                                                                : CompileStatus::Error);
}

std::string ProgramCompilation::filePath(int number, const std::string& extension) const {
    const std::string& directory = cell_.programDirectory();
    const auto program = cell_.program(slot_, number);
    if (directory.empty() || !program) return {};
    const fs::path dat = fs::path(directory) / program->name;
    std::error_code error;
    if (!fs::exists(dat, error)) return {};
    return (dat.parent_path() / (dat.stem().string() + "." + extension)).string();
}

CompileStatus ProgramCompilation::statusFromFiles(int number) const {
    fs::file_time_type source;
    if (!modified(filePath(number, "DAT"), source)) return CompileStatus::NotCompiled;
    // CF-013: an object file is never beside the errors of another compile,
    // so a current .NCO means compiled.
    fs::file_time_type time;
    if (modified(filePath(number, "NCO"), time) && time >= source) return CompileStatus::Compiled;
    const std::string errorFile = filePath(number, "ERR");
    if (modified(errorFile, time) && time >= source) {
        // C-014: only errors make status E (an .ERR with notices only, as
        // older versions wrote beside a good .NCO, does not)
        std::string text;
        if (std::string unread; !readFileText(errorFile, text, unread) || errorFileHasErrors(text))
            return CompileStatus::Error;
    }
    return CompileStatus::NotCompiled;
}

void ProgramCompilation::setStatus(int number, CompileStatus status) {
    status_[number] = status;
    changed(number);
}

void ProgramCompilation::setMessages(int number, std::vector<CompilerError> messages) {
    if (messages.empty())
        messages_.erase(number);
    else
        messages_[number] = std::move(messages);
    changed(number);
}

void ProgramCompilation::clearObjects(int number) {
    for (const char* extension : {"NCO", "ERR"}) {
        const std::string path = filePath(number, extension);
        std::string ignored;  // a file that cannot be removed is overwritten by the next compile
        if (!path.empty()) removeFile(path, ignored);
    }
    results_.erase(number);
    lookAhead_.erase(number);
    running_.erase(number);  // the store dropped its runtime version with the new source
}

bool ProgramCompilation::save(int number, const std::string& text, std::string& error) {
    const auto old = cell_.program(slot_, number);
    if (!old) {
        error = "program " + std::to_string(number) + " does not exist";
        return false;
    }
    const std::string path = filePath(number, "DAT");
    std::string reason;
    if (!path.empty() && !writeFileAtomically(path, text, reason)) {
        error = path + " not saved: " + reason;
        return false;
    }
    cell_.addProgram(slot_, number, old->name, text);
    clearObjects(number);
    messages_.erase(number);
    setStatus(number, CompileStatus::NotCompiled);
    return true;
}

bool ProgramCompilation::compile(int number, std::string& error) {
    lastRefusal_ = Refusal::None;
    const auto program = cell_.program(slot_, number);
    if (!program) {
        lastRefusal_ = Refusal::NoProgram;
        error = "program " + std::to_string(number) + " does not exist";
        return false;
    }
    if (!cell_.ncOptions().compilerActive) {
        lastRefusal_ = Refusal::CompilerOff;
        error = "the compiler is not active (NC options: Compiler active = No)";
        return false;
    }
    const CompilerOptions options = compilerOptions(number);
    if (!needsCompilation(*program, options) && cell_.ncOptions().userCompilers.empty()) {
        lastRefusal_ = Refusal::NothingToCompile;
        error = "the program uses no compiler keyword: nothing to compile";
        return false;
    }
    if (userCompilerBusy()) {
        lastRefusal_ = Refusal::UserCompilerBusy;
        error = "a user compiler runs: program " + std::to_string(number) +
                " is compiled when it is done";
        return false;
    }
    if (!cell_.ncOptions().userCompilers.empty()) {
        if (!refusedUserCompilers(number)) startBackground(number, program, options, true);
        return true;
    }
    auto result = std::make_shared<const CompileResult>(compileNow(number, *program, options));
    apply(number, std::move(result), lookAhead_[number], true);
    return true;
}

void ProgramCompilation::writeCompileFiles(int number, const CompileResult& result) {
    const std::string source = filePath(number, "DAT");
    if (source.empty()) return;  // a program without file (built-in demo)
    std::string errorPath;
    std::string reason;
    if (mtc::core::writeCompileFiles(source, "", result, errorPath, reason)) return;
    messages_[number].push_back(
        refusalOf(number, "FILE_WRITE", "Compile files not written", reason));
}

std::string ProgramCompilation::prepareRuntime(int number, DiagnosticList& diagnostics) {
    if (!cell_.program(slot_, number)) return {};  // the interpreter reports it
    if (std::string alarm = prepareOne(number, diagnostics); !alarm.empty()) return alarm;
    // Program 99 holds the labels a program calls: it runs compiled as well.
    if (number != 99 && cell_.program(slot_, 99)) return prepareOne(99, diagnostics);
    return {};
}

std::string ProgramCompilation::prepareOne(int number, DiagnosticList& diagnostics) {
    ProgramStore& store = cell_.store();
    auto runSource = [&] {
        store.putRuntime(process(), number, nullptr);
        running_.erase(number);
    };
    if (!cell_.ncOptions().compilerActive) {
        runSource();
        // Seed 001 ch. 7: with the compiler off, a compiler keyword is an
        // error at download, before any block of the program runs.
        Diagnostic keyword;
        if (findCompilerWord(*cell_.program(slot_, number), keyword)) {
            diagnostics.add(keyword);
            return formatDiagnostic(keyword, cell_.language());
        }
        return {};
    }
    CompileStatus current = status(number);
    if (current == CompileStatus::NotNeeded) {
        runSource();
        return {};
    }
    if (current == CompileStatus::NotCompiled) {
        std::string ignored;  // refused while a user compiler runs (below)
        compile(number, ignored);
        current = status(number);
    }
    const auto result = current == CompileStatus::Compiled ? runtimeResult(number) : nullptr;
    if (!result && userCompilerBusy()) {
        runSource();
        return alarmText("ALARM_START_USER_COMPILER_BUSY",
                         "Start refused: program %1 is being compiled (user compiler) \u2014 "
                         "Start again when done",
                         cell_.language(), {std::to_string(number)});
    }
    if (!result) {
        runSource();
        return alarmText("ALARM_START_COMPILER_ERRORS",
                         "Start refused: program %1 has compiler errors \u2014 see error window",
                         cell_.language(), {std::to_string(number)});
    }
    if (running(number) == result && store.findRuntime(process(), number)) return {};
    const auto source = cell_.program(slot_, number);
    ParseOptions options;
    options.programNumber = number;
    options.name = source->name;
    store.putRuntime(process(), number,
                     std::make_shared<Program>(parseProgram(result->objectText, options)));
    running_[number] = result;
    return {};
}

void ProgramCompilation::invalidate(const std::vector<int>& numbers) {
    for (int number : numbers) {
        if (running_.count(number)) cell_.store().putRuntime(process(), number, nullptr);
        clearObjects(number);
        status_.erase(number);  // no files any more: N
        messages_.erase(number);
    }
    needsCompiling_.clear();  // the global macros may have changed
    ++generation_;            // a compile running now used the old options
    changed(0);
}

int ProgramCompilation::sourceLineOf(int number, const std::string& block) const {
    const auto program = cell_.program(slot_, number);
    if (!program || block.empty()) return 0;
    const std::string_view text = program->source.view();
    int line = 1;
    for (std::size_t start = 0; start < text.size(); ++line) {
        const std::size_t at = text.find_first_not_of(" /:", start);
        if (at != std::string::npos && text.compare(at, block.size(), block) == 0) {
            const std::size_t after = at + block.size();
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

void ProgramCompilation::loadErrorFiles() {
    for (const auto& program : cell_.programs(slot_)) {
        if (status(program->number) != CompileStatus::Error) continue;
        std::string text;
        if (std::string unread; !readFileText(filePath(program->number, "ERR"), text, unread))
            continue;
        std::string identification;
        std::vector<CompilerError> errors = parseErrorFile(text, identification);
        for (CompilerError& error : errors) {
            if (error.program == 0) error.program = program->number;
            if (error.sourceLine == 0)
                error.sourceLine = sourceLineOf(program->number, error.block);
        }
        setMessages(program->number, std::move(errors));
    }
}

}  // namespace mtc::core
