#pragma once

#include <QWidget>

class QLabel;

namespace mtc::hmi {

class CellSession;

/// The header line of the panel: station, operating mode, selected program
/// and block, current alarm (labels headerStation/Mode/Program/Alarm).
class StatusHeader : public QWidget {
    Q_OBJECT
  public:
    explicit StatusHeader(QWidget* parent = nullptr);
    /// Shows the state of station `slot` of `session` under screen `title`.
    void show(const CellSession& session, int slot, const QString& title);

  private:
    QLabel* station_;
    QLabel* mode_;
    QLabel* program_;
    QLabel* screen_;
    QLabel* speed_;
    QLabel* alarm_;
};

}  // namespace mtc::hmi
