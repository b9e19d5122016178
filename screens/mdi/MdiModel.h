#pragma once

#include <QObject>
#include <QString>
#include <QStringList>
#include <QVector>
#include <memory>
#include <string>

#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/language/Program.h"

namespace mtc::hmi {
class CellSession;
class ProgramWorkspace;
}  // namespace mtc::hmi

namespace mtc::screens {

/// One MDI entry the station ran (or tried to run), newest last.
struct MdiHistoryItem {
    QString text;     ///< the input as typed
    QString outcome;  ///< "running", "done", "error line 2: ...", "reset"
};

/// Manual data input of one station (docs/decisions/mdi.md): the input the
/// operator types, the history of entries, and the station's MDI source
/// Start uses in MDI mode. Global macros come from the station's
/// ProgramWorkspace; refused input, parse and runtime errors go to its error
/// log with origin MDI and the input line. The input is never lost: only an
/// entry that ran to its end unchanged is cleared (MDI-004).
class MdiModel : public QObject {
    Q_OBJECT
  public:
    /// Installs itself as the MDI source of station `slot`'s clock.
    MdiModel(mtc::hmi::CellSession* session, int slot,
             std::shared_ptr<mtc::hmi::ProgramWorkspace> workspace, QObject* parent = nullptr);
    ~MdiModel() override;

    const QString& input() const { return input_; }
    /// The operator changed the input.
    void setInput(const QString& text);
    /// Checks the input (macros, keywords, syntax) without running it; the
    /// result is message(). True when Start could run it.
    bool check();
    /// Puts history item `row` back into the input (false: no such item).
    bool recall(int row);
    const QVector<MdiHistoryItem>& history() const { return history_; }
    /// The last message for the operator and whether it is an error.
    const QString& message() const { return message_; }
    bool messageIsError() const { return messageIsError_; }

    /// "MDI mode, ready" / "automatic mode: Start runs the selected program" ...
    QString modeSummary() const;
    /// "X 10.000  Y 0.000  Z -5.000" (programmed positions of the station).
    QString positionSummary() const;
    /// "G1 G17 G90 G94  F1000  S0  T0": the modal state MDI continues from.
    QString modalSummary() const;

    /// History entries kept (oldest dropped first).
    static constexpr int kMaxHistory = 50;

  signals:
    /// Input, history, message or the station's state changed.
    void changed();

  private:
    /// The MDI source of the clock: the program for Start, or an alarm.
    std::string provide(mtc::core::ProgramPtr& program);
    void ended(bool completed);
    /// Puts `diagnostics` into the error log (origin MDI) and the message.
    void report(const mtc::core::DiagnosticList& diagnostics, const QString& text);
    void setMessage(const QString& text, bool error);

    mtc::hmi::CellSession* session_;
    int slot_;
    std::shared_ptr<mtc::hmi::ProgramWorkspace> workspace_;
    QString input_;
    QString running_;  ///< text of the entry that runs ("" = none)
    QVector<MdiHistoryItem> history_;
    QString message_;
    bool messageIsError_ = false;
};

}  // namespace mtc::screens
