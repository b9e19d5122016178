#pragma once

#include <QObject>
#include <QString>
#include <QStringList>
#include <deque>

#include "cnc_core/mdi/MdiSession.h"

namespace mtc::hmi {
class CellSession;
}  // namespace mtc::hmi

namespace mtc::screens {

/// The MDI screen's view of a station's manual data input
/// (mtc::core::MdiSession, docs/decisions/mdi.md): it forwards the
/// operator's edits and keys to the station and renders what the station
/// holds (input, history, message, mode); the station owns the behaviour,
/// its diagnostics reach the error window through the station's log.
class MdiModel : public QObject {
    Q_OBJECT
  public:
    MdiModel(mtc::hmi::CellSession* session, int slot, QObject* parent = nullptr);

    QString input() const;
    /// The operator changed the input.
    void setInput(const QString& text);
    /// Checks the input (macros, keywords, syntax) without running it; the
    /// result is message(). True when Start could run it.
    bool check();
    /// Puts history item `row` back into the input (false: no such item).
    bool recall(int row);
    const std::deque<mtc::core::MdiHistoryItem>& history() const;
    /// The last message for the operator and whether it is an error.
    QString message() const;
    bool messageIsError() const;
    /// "MDI mode, ready" / "automatic mode: Start runs the selected program" ...
    QString modeSummary() const;
    /// "X 10.000  Y 0.000  Z -5.000": the programmed positions MDI continues
    /// from; while the axes work off blocks the interpreter has left behind
    /// (a program runs with look-ahead), their actual workpiece positions.
    QString positionSummary() const;
    /// The axes work off a block the interpreter has left behind (a program
    /// runs with look-ahead): the summaries are the running block's.
    bool showsRunningBlock() const;
    /// "G1 G17 G90 G94  F1000  S0  T0": the modal state MDI continues from,
    /// or that of the block the axes execute while they lag behind.
    QString modalSummary() const;

  signals:
    /// Input, history, message or the station's state changed.
    void changed();

  private:
    const mtc::core::MdiSession& mdi() const;

    mtc::hmi::CellSession* session_;
    int slot_;
};

}  // namespace mtc::screens
