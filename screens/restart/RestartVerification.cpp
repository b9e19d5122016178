#include "screens/restart/RestartVerification.h"

#include <QElapsedTimer>
#include <QLocale>

#include "hmi/CellSession.h"
#include "hmi/PanelLanguage.h"

namespace mtc::screens {

namespace {
constexpr int kTickMs = 15;
/// Work per tick, so the panel answers while a large program is verified.
constexpr qint64 kTickBudgetNs = 8'000'000;
constexpr std::uint64_t kArrivalsPerSlice = 16;

/// ADJUST / REPOS included; every run reads the station's tool list and
/// zero offsets, as the restart itself does.
mtc::core::VerifyOptions panelOptions(mtc::hmi::CellSession& session, int process) {
    mtc::core::VerifyOptions options;
    options.adjust = true;
    options.tools = session.setupData().tools(process);
    options.zeroOffsets = session.setupData().offsets(process);
    return options;
}
}  // namespace

RestartVerification::RestartVerification(mtc::hmi::CellSession* session, int slot, QObject* parent)
    : QObject(parent), session_(session), slot_(slot) {
    timer_.setInterval(kTickMs);
    connect(&timer_, &QTimer::timeout, this, &RestartVerification::tick);
}

RestartVerification::~RestartVerification() = default;

bool RestartVerification::startProgram(int program, QString& why) {
    timer_.stop();
    verifier_ = std::make_unique<mtc::core::RestartVerifier>(
        session_->config(), session_->processConfig(slot_).index, session_->store(),
        panelOptions(*session_, session_->processConfig(slot_).index));
    mtc::core::DiagnosticList diagnostics;
    if (!verifier_->begin(program, diagnostics, &session_->interpreter(slot_).state())) {
        why = diagnostics.items().empty() ? tr("program %1 cannot be verified").arg(program)
                                          : hmi::coreMessageLine(diagnostics.items().front());
        verifier_.reset();
        return false;
    }
    program_ = program;
    timer_.start();
    emit progressed();
    return true;
}

void RestartVerification::tick() {
    QElapsedTimer clock;
    clock.start();
    while (verifier_ && !verifier_->done() && clock.nsecsElapsed() < kTickBudgetNs)
        verifier_->advance(kArrivalsPerSlice);
    if (!verifier_ || verifier_->done()) {
        timer_.stop();
        emit finished();
    }
    emit progressed();
}

const mtc::core::VerifyReport* RestartVerification::programReport() const {
    return verifier_ ? &verifier_->report() : nullptr;
}

QString RestartVerification::programText() const {
    if (!verifier_) return {};
    const mtc::core::VerifyReport& report = verifier_->report();
    if (!verifier_->done())
        return tr("Verifying P%1: %2 arrivals checked …")
            .arg(program_)
            .arg(QLocale::c().toString(static_cast<qulonglong>(report.arrivals)));
    QString text = tr("Verification of P%1: %2")
                       .arg(program_)
                       .arg(QString::fromStdString(report.coverageLine()));
    for (const auto& d : report.diagnostics.items())
        if (d.severity == mtc::core::Severity::Error) {
            text += " — " + hmi::coreMessageLine(d);
            break;
        }
    return text;
}

void RestartVerification::verifyTarget(const mtc::core::RestartSelection& selection,
                                       const mtc::core::InterpreterState& before) {
    mtc::core::RestartVerifier verifier(
        session_->config(), session_->processConfig(slot_).index, session_->store(),
        panelOptions(*session_, session_->processConfig(slot_).index));
    target_ = verifier.verifySelection(selection, &before);
}

}  // namespace mtc::screens
