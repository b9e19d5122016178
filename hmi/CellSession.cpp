#include "hmi/CellSession.h"

#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/afc/AfcMotion.h"
#include "cnc_core/afc/AfcTrendRecorder.h"
#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/language/Parser.h"
#include "cnc_core/machine/SimulatedMachine.h"
#include "cnc_core/machine_data/SharedMachineDataFile.h"
#include "cnc_core/machine_data/MachineDataStore.h"
#include "hmi/NcOptionsHolder.h"
#include "hmi/SimulationClock.h"

namespace mtc::hmi {

namespace {
/// The configuration's tool lists and zero offsets (its problems are the
/// interpreters' configuration diagnostics).
mtc::core::SetupData setupDataOf(const mtc::core::MachineConfig& config) {
    mtc::core::DiagnosticList ignored;
    return mtc::core::SetupData::fromConfig(config, ignored);
}
}  // namespace

/// Everything one process of the cell runs on.
struct CellSession::Station {
    Station(const mtc::core::ProcessConfig& config, const mtc::core::ProgramStore& store,
            const mtc::core::InterpreterServices& services, mtc::core::MachineDataStore& data)
        : control(config.index),
          afc(std::make_shared<mtc::core::AdaptiveFeedControl>(
              config, data, mtc::core::torqueModelFromConfig(config), &control.signalTable())),
          machine(config),
          interpreter(config, store, machine, services),
          clock(interpreter, machine, control) {
        control.setRunner(&clock);
        machine.attachAdaptiveFeed(afc.get(), &trend);
        interpreter.setAdaptiveFeed(afc);
    }
    mtc::core::ProcessControl control;
    std::shared_ptr<mtc::core::AdaptiveFeedControl> afc;
    mtc::core::AfcTrendRecorder trend;
    mtc::core::SimulatedMachine machine;
    mtc::core::Interpreter interpreter;
    SimulationClock clock;
};

CellSession::CellSession(mtc::core::MachineConfig config, QObject* parent)
    : QObject(parent),
      config_(std::move(config)),
      machineData_(std::make_shared<mtc::core::MachineDataStore>(config_)),
      setupData_(setupDataOf(config_)) {
    mtc::core::InterpreterServices services;
    services.machineData = machineData_;
    services.axisTransfer = &axisTransfer_;  // GAX / FAX of normal runs
    for (int slot = 0; slot < processCount(); ++slot) {
        services.tools = setupData_.tools(processConfig(slot).index);
        services.zeroOffsets = setupData_.offsets(processConfig(slot).index);
        stations_.push_back(
            std::make_unique<Station>(processConfig(slot), store_, services, *machineData_));
        connect(&stations_.back()->clock, &SimulationClock::changed, this,
                [this, slot] { emit processChanged(slot); });
    }
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
    connect(&refreshTimer_, &QTimer::timeout, this, [this] { refreshMachineData(); });
    ncOptions_ = std::make_unique<NcOptionsHolder>(this);
}

void CellSession::setProgramDirectory(const QString& directory) {
    programDirectory_ = directory;
    ncOptions_->load(directory);
}

CellSession::~CellSession() {
    if (machineDataUnsaved()) {  // nothing the NC wrote is lost at exit
        QString error;
        saveMachineData(error);
    }
}

bool CellSession::machineDataUnsaved() const {
    return !machineDataFile_.isEmpty() && machineData_->revision() != savedRevision_;
}

const mtc::core::ProcessConfig& CellSession::processConfig(int slot) const {
    return config_.processes.at(static_cast<size_t>(slot));
}

mtc::core::ProcessControl& CellSession::control(int slot) {
    return stations_.at(static_cast<size_t>(slot))->control;
}

const mtc::core::ProcessControl& CellSession::control(int slot) const {
    return stations_.at(static_cast<size_t>(slot))->control;
}

mtc::core::Interpreter& CellSession::interpreter(int slot) {
    return stations_.at(static_cast<size_t>(slot))->interpreter;
}

mtc::core::SimulatedMachine& CellSession::machine(int slot) {
    return stations_.at(static_cast<size_t>(slot))->machine;
}

SimulationClock& CellSession::clock(int slot) {
    return stations_.at(static_cast<size_t>(slot))->clock;
}

mtc::core::AdaptiveFeedControl& CellSession::adaptiveFeed(int slot) {
    return *stations_.at(static_cast<size_t>(slot))->afc;
}

const mtc::core::AfcTrendRecorder& CellSession::afcTrend(int slot) const {
    return stations_.at(static_cast<size_t>(slot))->trend;
}

int CellSession::slotOfProcess(int process) const {
    for (int slot = 0; slot < processCount(); ++slot)
        if (processConfig(slot).index == process) return slot;
    return -1;
}

void CellSession::addProgram(int slot, int number, const std::string& name, std::string text) {
    mtc::core::ParseOptions options;
    options.programNumber = number;
    options.name = name;
    putProgram(
        slot, number,
        std::make_shared<mtc::core::Program>(mtc::core::parseProgram(std::move(text), options)));
}

void CellSession::putProgram(int slot, int number, mtc::core::ProgramPtr program) {
    store_.put(processConfig(slot).index, number, std::move(program));
    emit processChanged(slot);
}

std::vector<mtc::core::ProgramPtr> CellSession::programs(int slot) const {
    std::vector<mtc::core::ProgramPtr> list;
    const int process = processConfig(slot).index;
    for (const auto& [key, program] : store_.programs())
        if (key.first == process) list.push_back(program);
    return list;
}

mtc::core::ProgramPtr CellSession::program(int slot, int number) const {
    return store_.findSource(processConfig(slot).index, number);
}

bool CellSession::pressKey(int slot, mtc::core::ControlKey key) {
    bool ok = control(slot).press(key);
    emit processChanged(slot);
    return ok;
}

bool CellSession::selectProgram(int slot, int number) {
    bool ok = control(slot).selectProgram(number);
    // The runtime program (compiled when the source has compiler keywords)
    // is what the station and its NC program restart work on (C-013).
    if (ok && number > 0) {
        const std::string alarm = clock(slot).prepare(number);
        if (!alarm.empty()) control(slot).setAlarm(alarm);
    }
    emit processChanged(slot);
    return ok;
}

QStringList CellSession::openMachineDataFile(const QString& path) {
    machineDataFile_ = path;
    machineDataMessages_.clear();
    sharedData_.reset();
    refreshTimer_.stop();
    if (path.isEmpty()) return machineDataMessages_;
    sharedData_ = std::make_unique<mtc::core::SharedMachineDataFile>(path.toStdString());
    const mtc::core::MachineDataLoadResult result = sharedData_->open(*machineData_);
    savedRevision_ = machineData_->revision();
    for (const mtc::core::Diagnostic& d : result.diagnostics.items())
        machineDataMessages_ << QString::fromStdString(d.message);
    // Tool lists and zero offsets beside it (a refused file changes nothing).
    mtc::core::DiagnosticList setup;
    setupData_.load(mtc::core::setupDataFilesBeside(path.toStdString()), setup);
    for (const mtc::core::Diagnostic& d : setup.items())
        machineDataMessages_ << QString::fromStdString(d.message);
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
    const std::uint64_t before = machineData_->revision();
    const mtc::core::MachineDataSync sync = sharedData_->save(*machineData_);
    for (const mtc::core::Diagnostic& d : sync.diagnostics.items())
        machineDataMessages_ << QString::fromStdString(d.message);
    if (!sync.ok) {
        error = QString::fromStdString(sync.error);
        return false;
    }
    // The saved revision: what the store holds now (the take-over included),
    // unless the NC changed something since the save began (then: unsaved).
    savedRevision_ = sync.takenOver > 0 ? machineData_->revision() : before;
    if (sync.takenOver > 0) {
        machineDataMessages_ << takeOverMessage(machineDataFile_, sync.takenOver);
        emit machineDataNotice(machineDataMessages_.back());
        for (int slot = 0; slot < processCount(); ++slot)
            emit processChanged(slot);
    }
    return true;
}

int CellSession::refreshMachineData() {
    if (!sharedData_) return 0;
    const bool unsaved = machineDataUnsaved();
    const mtc::core::MachineDataSync sync = sharedData_->refresh(*machineData_);
    if (!sync.ok || sync.takenOver == 0) return 0;
    if (!unsaved) savedRevision_ = machineData_->revision();  // the store is the file again
    machineDataMessages_ << takeOverMessage(machineDataFile_, sync.takenOver);
    emit machineDataNotice(machineDataMessages_.back());
    for (int slot = 0; slot < processCount(); ++slot)
        emit processChanged(slot);
    return static_cast<int>(sync.takenOver);
}

}  // namespace mtc::hmi
