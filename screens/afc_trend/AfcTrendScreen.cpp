#include "screens/afc_trend/AfcTrendScreen.h"

#include <QBuffer>
#include <QDir>
#include <QLabel>
#include <QVBoxLayout>

#include "cnc_core/afc/AdaptiveFeedControl.h"
#include "cnc_core/afc/AfcTrendRecorder.h"
#include "cnc_core/program/AtomicWrite.h"
#include "hmi/CellSession.h"
#include "screens/afc_trend/AfcTrendPlot.h"

namespace mtc::screens {
namespace {

/// Samples of the last `window` seconds (all when window <= 0).
std::vector<mtc::core::AfcTrendSample> lastSeconds(const mtc::core::AfcTrendRecorder& recorder,
                                                   double window) {
    std::vector<mtc::core::AfcTrendSample> samples = recorder.samples();
    if (window <= 0 || samples.empty()) return samples;
    const double from = samples.back().time - window;
    auto first =
        std::find_if(samples.begin(), samples.end(),
                     [from](const mtc::core::AfcTrendSample& s) { return s.time >= from; });
    samples.erase(samples.begin(), first);
    return samples;
}

QString statusText(const mtc::core::AfcTrendRecorder& recorder) {
    if (recorder.size() == 0)
        return AfcTrendScreen::tr(
            "No trend yet (adaptive feed control records during feed moves).");
    const mtc::core::AfcTrendSample s = recorder.at(recorder.size() - 1);
    return AfcTrendScreen::tr(
               "t = %1 s   %2   actual %3 %   machining %4 %   reduction %5 % (peak %6 %)   "
               "feed %7 mm/min   idling 005 %8 % (max. 006 %9 %)   stall 014 %10 %   "
               "EXCTH %11   THMIS %12   samples %13")
        .arg(s.time, 0, 'f', 2)
        .arg(s.measuringIdle ? QString("ITM")
             : s.active      ? AfcTrendScreen::tr("G26 on")
                             : AfcTrendScreen::tr("G26 off"))
        .arg(s.torqueActual, 0, 'f', 1)
        .arg(s.machiningTorque, 0, 'f', 1)
        .arg(s.feedReduction, 0, 'f', 1)
        .arg(s.peakReduction, 0, 'f', 1)
        .arg(s.effectiveFeed, 0, 'f', 0)
        .arg(s.idleTorque, 0, 'f', 1)
        .arg(s.maximumIdleTorque, 0, 'f', 1)
        .arg(s.stallTorque, 0, 'f', 1)
        .arg(s.excessiveThrust ? 1 : 0)
        .arg(s.thrustMissing ? 1 : 0)
        .arg(recorder.size());
}

}  // namespace

AfcTrendScreen::AfcTrendScreen(const mtc::hmi::ScreenContext& context)
    : Screen(context), exportDirectory_(QDir::currentPath()) {
    plot_ = new AfcTrendPlot(this);
    status_ = new QLabel(this);
    status_->setObjectName("afcTrendStatus");
    message_ = new QLabel(this);
    message_->setObjectName("afcTrendMessage");
    for (QLabel* label : {status_, message_}) {  // long texts wrap, never widen the window
        label->setWordWrap(true);
        label->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    }
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(plot_, 1);
    layout->addWidget(status_);
    layout->addWidget(message_);
    setFocusPolicy(Qt::StrongFocus);
    connect(context.session, &mtc::hmi::CellSession::processChanged, this, [this](int slot) {
        if (slot == this->context().process && isVisible()) refresh(false);
    });
}

void AfcTrendScreen::activated() {
    refresh(true);
}

void AfcTrendScreen::showEvent(QShowEvent* event) {
    Screen::showEvent(event);
    refresh(false);  // samples recorded while the screen was hidden
}

void AfcTrendScreen::refresh(bool force) {
    const auto& recorder = context().session->afcTrend(context().process);
    if (!force && recorder.revision() == shownRevision_) return;
    shownRevision_ = recorder.revision();
    plot_->setSamples(lastSeconds(recorder, windowSeconds_));
    status_->setText(statusText(recorder));
}

void AfcTrendScreen::cycleWindow() {
    windowSeconds_ = windowSeconds_ == 10.0 ? 60.0 : windowSeconds_ == 60.0 ? 0.0 : 10.0;
    setMessage(windowSeconds_ > 0 ? tr("Window: last %1 s").arg(windowSeconds_)
                                  : tr("Window: every sample kept"));
    refresh(true);
    emit softKeysChanged();
}

QString AfcTrendScreen::exportPath(const char* suffix) const {
    const int process = context().session->processConfig(context().process).index;
    return QDir(exportDirectory_).filePath(QString("afc-trend-P%1.%2").arg(process).arg(suffix));
}

void AfcTrendScreen::setMessage(const QString& text) {
    message_->setText(text);
}

void AfcTrendScreen::exportPng() {
    refresh(true);
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    if (!plot_->grab().save(&buffer, "PNG")) return setMessage(tr("PNG export failed: no image"));
    const QString path = exportPath("png");
    std::string error;
    if (!mtc::core::writeFileAtomically(path.toStdString(),
                                        std::string_view(bytes.constData(), bytes.size()), error))
        return setMessage(tr("PNG export failed: %1").arg(QString::fromStdString(error)));
    setMessage(tr("Trend written to %1").arg(path));
}

void AfcTrendScreen::exportCsv() {
    const QString path = exportPath("csv");
    std::string error;
    const std::string csv = context().session->afcTrend(context().process).csv();
    if (!mtc::core::writeFileAtomically(path.toStdString(), csv, error))
        return setMessage(tr("CSV export failed: %1").arg(QString::fromStdString(error)));
    setMessage(tr("Trend written to %1").arg(path));
}

mtc::hmi::SoftKeys AfcTrendScreen::softKeys() {
    mtc::hmi::SoftKeys keys(8);
    keys[0] = {windowSeconds_ == 10.0   ? tr("Window\n10 s")
               : windowSeconds_ == 60.0 ? tr("Window\n60 s")
                                        : tr("Window\nall"),
               [this] { cycleWindow(); }};
    keys[1] = {tr("Export\nPNG"), [this] { exportPng(); }};
    keys[2] = {tr("Export\nCSV"), [this] { exportCsv(); }};
    keys[7] = {tr("Back"), [this] { emit navigateTo("menu"); }};
    return keys;
}

}  // namespace mtc::screens
