#pragma once

#include <QString>
#include <cstdint>

#include "hmi/Screen.h"

class QLabel;

namespace mtc::screens {

class AfcTrendPlot;

/// Adaptive feed trend of the station (seed 002 Fig. 2-1 as a live plot):
/// the samples the simulated machine records while feed moves run, over a
/// window of simulated time. Soft keys: F1 window (10 s / 60 s / all),
/// F2 export PNG, F3 export CSV (both written atomically into the export
/// directory as afc-trend-P<process>.png/.csv), F8 back.
class AfcTrendScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    explicit AfcTrendScreen(const mtc::hmi::ScreenContext& context);
    QString screenName() const override { return "afc-trend"; }
    QString title() const override {
        return QCoreApplication::translate("ScreenTitle", "Adaptive feed trend");
    }
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;

    /// Where the exports go (default: the current directory).
    void setExportDirectory(const QString& directory) { exportDirectory_ = directory; }
    /// Seconds of simulated time shown (0 = every sample kept).
    double windowSeconds() const { return windowSeconds_; }

  protected:
    void showEvent(QShowEvent* event) override;

  private:
    void refresh(bool force);
    void cycleWindow();
    void exportPng();
    void exportCsv();
    QString exportPath(const char* suffix) const;
    void setMessage(const QString& text);

    AfcTrendPlot* plot_;
    QLabel* status_;
    QLabel* message_;
    QString exportDirectory_;
    double windowSeconds_ = 10.0;
    std::uint64_t shownRevision_ = ~std::uint64_t{0};
};

}  // namespace mtc::screens
