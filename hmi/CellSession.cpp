#include "hmi/CellSession.h"

#include <algorithm>
#include <cmath>

#include "cnc_core/machine_data/MachineDataStore.h"
#include "cnc_core/machine_data/SharedMachineDataFile.h"
#include "cnc_core/tooldata/SetupDataEditor.h"
#include "hmi/NcOptionsHolder.h"
#include "hmi/PanelLanguage.h"

namespace mtc::hmi {

namespace {
/// Longest real time one tick makes up for (a stalled event loop does not
/// make the machine jump).
constexpr double kMaxTickSeconds = 0.25;
/// As fast as possible: simulated time one advance() may cover, and the
/// wall time a tick may use before the panel handles events again.
constexpr double kMaxSpeedStep = 3600.0;
constexpr qint64 kTickBudgetNs = 8'000'000;
}  // namespace

CellSession::CellSession(mtc::core::MachineConfig config, QObject* parent)
    : QObject(parent), cell_(std::move(config)) {
    announced_.assign(static_cast<std::size_t>(cell_.stationCount()), 0);
    for (int slot = 0; slot < cell_.stationCount(); ++slot) {
        cell_.station(slot).setRunTracing(true);   // the toolpath view's backplot (TP-016)
        cell_.station(slot).setLiveCutting(true);  // and its part cut live (TP-027)
    }
    // Alarms and MDI messages built from a diagnostic in the panel's language
    // (installed before the session is made; D-024).
    cell_.setLanguage(installedCoreLanguage());
    timer_.setInterval(kTickMs);
    connect(&timer_, &QTimer::timeout, this, &CellSession::tick);
    realTime_.start();
    timer_.start();
    saveTimer_.setSingleShot(true);
    saveTimer_.setInterval(kNcSaveDelayMs);
    connect(&saveTimer_, &QTimer::timeout, this, [this] {
        QString error;
        autoSaveError_ = saveMachineData(error) ? QString() : error;
    });
    // Every change of a station may come with MTD writes or page 30 status.
    connect(this, &CellSession::processChanged, this, [this] {
        if (machineDataUnsaved() && sharedData_ && sharedData_->mayOverwrite() &&
            !saveTimer_.isActive())
            saveTimer_.start();
    });
    refreshTimer_.setInterval(kRefreshMs);
    connect(&refreshTimer_, &QTimer::timeout, this, [this] {
        refreshMachineData();
        refreshSetupData();
    });
    ncOptions_ = std::make_unique<NcOptionsHolder>(this);
    setupEditor_ =
        std::make_unique<mtc::core::SetupDataEditor>(setupData(), mtc::core::SetupDataFiles{});
}

void CellSession::setProgramDirectory(const QString& directory) {
    programDirectory_ = directory;
    cell_.setProgramDirectory(directory.toStdString());
    ncOptions_->load(directory);
}

CellSession::~CellSession() {
    if (machineDataUnsaved()) {  // nothing the NC wrote is lost at exit
        QString error;
        saveMachineData(error);
    }
}

bool CellSession::machineDataUnsaved() const {
    return !machineDataFile_.isEmpty() && cell_.sharedMachineData()->revision() != savedRevision_;
}

const mtc::core::ProcessConfig& CellSession::processConfig(int slot) const {
    return station(slot).config();
}

void CellSession::addProgram(int slot, int number, const std::string& name, std::string text) {
    cell_.addProgram(slot, number, name, std::move(text));
    emit processChanged(slot);
}

void CellSession::announcePrograms(int slot) {
    emit processChanged(slot);
}

void CellSession::putProgram(int slot, int number, mtc::core::ProgramPtr program) {
    cell_.putProgram(slot, number, std::move(program));
    emit processChanged(slot);
}

bool CellSession::pressKey(int slot, mtc::core::ControlKey key) {
    const bool ok = station(slot).press(key);
    announceChanges();
    emit processChanged(slot);
    return ok;
}

bool CellSession::selectProgram(int slot, int number) {
    const bool ok = station(slot).selectProgram(number);
    announceChanges();
    emit processChanged(slot);
    return ok;
}

void CellSession::setSpeed(double factor) {
    speed_ = std::isfinite(factor) && factor > 0 ? factor : kMaxSpeed;
    emit speedChanged();
}

void CellSession::cycleSpeed() {
    if (speed_ == 1.0)
        setSpeed(10.0);
    else if (speed_ == 10.0)
        setSpeed(kMaxSpeed);
    else
        setSpeed(1.0);
}

QString CellSession::speedText() const {
    if (speed_ == kMaxSpeed) return "max";
    return QString("\u00d7%1").arg(speed_);
}

void CellSession::setTimerEnabled(bool enabled) {
    if (enabled && !timer_.isActive()) {
        realTime_.restart();
        timer_.start();
    }
    if (!enabled) timer_.stop();
}

void CellSession::advance(double seconds) {
    cell_.advance(seconds);
    announceChanges();
}

void CellSession::tick() {
    QElapsedTimer budget;
    budget.start();
    const double real = std::min(realTime_.restart() / 1000.0, kMaxTickSeconds);
    if (speed_ != kMaxSpeed) {
        cell_.advance(real * speed_);
    } else {
        do
            cell_.advance(kMaxSpeedStep);
        while (anyStation(&mtc::core::Station::running) && budget.nsecsElapsed() < kTickBudgetNs);
    }
    // A restart computing process only needs processor time: back-to-back
    // slices within the tick's budget, and the next tick at once.
    while (anyStation(&mtc::core::Station::computing) && budget.nsecsElapsed() < kTickBudgetNs)
        for (int slot = 0; slot < cell_.stationCount(); ++slot)
            if (cell_.station(slot).computing()) cell_.station(slot).advance(0.0);
    timer_.setInterval(anyStation(&mtc::core::Station::computing) ? 0 : kTickMs);
    announceChanges();
}

bool CellSession::anyStation(bool (mtc::core::Station::*state)() const) const {
    for (int slot = 0; slot < cell_.stationCount(); ++slot)
        if ((cell_.station(slot).*state)()) return true;
    return false;
}

void CellSession::announceChanges() {
    for (int slot = 0; slot < cell_.stationCount(); ++slot) {
        const std::uint64_t revision = cell_.station(slot).revision();
        if (revision == announced_[static_cast<std::size_t>(slot)]) continue;
        announced_[static_cast<std::size_t>(slot)] = revision;
        emit processChanged(slot);
    }
}

QStringList CellSession::openMachineDataFile(const QString& path) {
    machineDataFile_ = path;
    machineDataMessages_.clear();
    sharedData_.reset();
    refreshTimer_.stop();
    setupEditor_ =
        std::make_unique<mtc::core::SetupDataEditor>(setupData(), mtc::core::SetupDataFiles{});
    if (path.isEmpty()) return machineDataMessages_;
    sharedData_ = std::make_unique<mtc::core::SharedMachineDataFile>(path.toStdString());
    const mtc::core::MachineDataLoadResult result = sharedData_->open(machineData());
    savedRevision_ = machineData().revision();
    for (const mtc::core::Diagnostic& d : result.diagnostics.items())
        machineDataMessages_ << coreMessageLine(d);
    // Tool lists and zero offsets beside it (a refused file changes nothing);
    // the editor looks at the files before they are read (SetupDataEditor).
    const mtc::core::SetupDataFiles files = mtc::core::setupDataFilesBeside(path.toStdString());
    setupEditor_ = std::make_unique<mtc::core::SetupDataEditor>(setupData(), files);
    mtc::core::DiagnosticList setup;
    setupData().load(files, setup);
    for (const mtc::core::Diagnostic& d : setup.items())
        machineDataMessages_ << coreMessageLine(d);
    refreshTimer_.start();
    for (int slot = 0; slot < processCount(); ++slot)
        emit processChanged(slot);
    return machineDataMessages_;
}

/// Tells the user what a save or a refresh took over from another program.
static QString takeOverMessage(const QString& file, std::size_t count) {
    return QString("%1 value(s) changed by another program in %2 were taken over")
        .arg(count)
        .arg(file);
}

bool CellSession::saveMachineData(QString& error) {
    if (!sharedData_) return true;
    const std::uint64_t before = machineData().revision();
    const mtc::core::MachineDataSync sync = sharedData_->save(machineData());
    for (const mtc::core::Diagnostic& d : sync.diagnostics.items())
        machineDataMessages_ << coreMessageLine(d);
    if (!sync.ok) {
        error = QString::fromStdString(sync.error);
        return false;
    }
    // The saved revision: what the store holds now (the take-over included),
    // unless the NC changed something since the save began (then: unsaved).
    savedRevision_ = sync.takenOver > 0 ? machineData().revision() : before;
    if (sync.takenOver > 0) {
        machineDataMessages_ << takeOverMessage(machineDataFile_, sync.takenOver);
        emit machineDataNotice(machineDataMessages_.back());
        for (int slot = 0; slot < processCount(); ++slot)
            emit processChanged(slot);
    }
    return true;
}

void CellSession::refreshSetupData() {
    mtc::core::DiagnosticList notes;
    const bool takenOver = setupEditor_->refresh(notes);
    for (const mtc::core::Diagnostic& d : notes.items())
        machineDataMessages_ << coreMessageLine(d);
    if (!notes.empty()) emit setupDataNotice(coreMessageLine(notes.items().back()));
    if (takenOver)
        for (int slot = 0; slot < processCount(); ++slot)
            emit processChanged(slot);
}

int CellSession::refreshMachineData() {
    if (!sharedData_) return 0;
    const bool unsaved = machineDataUnsaved();
    const mtc::core::MachineDataSync sync = sharedData_->refresh(machineData());
    if (!sync.ok || sync.takenOver == 0) return 0;
    if (!unsaved) savedRevision_ = machineData().revision();  // the store is the file again
    machineDataMessages_ << takeOverMessage(machineDataFile_, sync.takenOver);
    emit machineDataNotice(machineDataMessages_.back());
    for (int slot = 0; slot < processCount(); ++slot)
        emit processChanged(slot);
    return static_cast<int>(sync.takenOver);
}

}  // namespace mtc::hmi
