#include "hmi/CellSession.h"

#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/afc/AfcMotion.h"
#include "cnc_core/afc/AfcTrendRecorder.h"
#include "cnc_core/interp/Interpreter.h"
#include "cnc_core/language/Parser.h"
#include "cnc_core/machine/SimulatedMachine.h"
#include "cnc_core/machine_data/MachineDataFile.h"
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
        if (machineDataUnsaved() && machineDataWritable_ && !saveTimer_.isActive())
            saveTimer_.start();
    });
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
    machineDataWritable_ = true;
    machineDataMessages_.clear();
    if (path.isEmpty()) return machineDataMessages_;
    const mtc::core::MachineDataLoadResult result =
        mtc::core::MachineDataFile(path.toStdString()).load(*machineData_);
    machineDataWritable_ = result.mayOverwrite;
    savedRevision_ = machineData_->revision();
    for (const mtc::core::Diagnostic& d : result.diagnostics.items())
        machineDataMessages_ << QString::fromStdString(d.message);
    // Tool lists and zero offsets beside it (a refused file changes nothing).
    mtc::core::DiagnosticList setup;
    setupData_.load(mtc::core::setupDataFilesBeside(path.toStdString()), setup);
    for (const mtc::core::Diagnostic& d : setup.items())
        machineDataMessages_ << QString::fromStdString(d.message);
    for (int slot = 0; slot < processCount(); ++slot)
        emit processChanged(slot);
    return machineDataMessages_;
}

bool CellSession::saveMachineData(QString& error) {
    if (machineDataFile_.isEmpty()) return true;
    if (!machineDataWritable_) {
        error = "the damaged machine data file could not be kept aside; not overwritten";
        return false;
    }
    std::string reason;
    const std::uint64_t revision = machineData_->revision();
    if (mtc::core::MachineDataFile(machineDataFile_.toStdString()).save(*machineData_, reason)) {
        savedRevision_ = revision;
        return true;
    }
    error = QString::fromStdString(reason);
    return false;
}

}  // namespace mtc::hmi
