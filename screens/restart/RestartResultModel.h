#pragma once

#include <QAbstractTableModel>
#include <QVector>

namespace mtc::screens {

class RestartCollisions;
class RestartRun;
class RestartVerification;

/// The state the computing process restored at the target block next to the
/// state the machine had when the restart was accepted (seed 000, 2.8, 3.1,
/// 4.1, 4.2): G groups, M groups 1..15, last M(16) and Q, S / T / E / D / F,
/// page 60 and the M(16) and Q buffers of page 61. Rows that differ are
/// highlighted. Columns: item, at the target, machine before the restart.
class RestartResultModel : public QAbstractTableModel {
    Q_OBJECT
  public:
    /// Role: true when the row's two values differ.
    static constexpr int DiffersRole = Qt::UserRole + 1;
    /// Role: true on a row that lists a collision of the way back (D-021).
    static constexpr int CollisionRole = Qt::UserRole + 2;
    /// Role: true on a heading row ("G functions", "Page 60", ...), whose
    /// title the review shows across every column.
    static constexpr int SectionRole = Qt::UserRole + 3;

    /// Rows of `run`, the verification of its target and the check of its
    /// way back against the part (all must outlive the model); empty until
    /// reload(). The collisions come first, in red, and stay in the
    /// differences-only view.
    RestartResultModel(const RestartRun* run, const RestartVerification* verification,
                       const RestartCollisions* collisions, QObject* parent = nullptr);

    /// Re-reads the run (after a computing process).
    void reload();
    /// Shows only the rows that differ (or all).
    void setDifferencesOnly(bool only);
    bool differencesOnly() const { return differencesOnly_; }
    /// Number of rows that differ (whatever the filter).
    int differenceCount() const;
    /// "re-established", "3 differences", "not verified yet" (the verification rows).
    QString verificationSummary() const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

    /// One line of the table.
    struct Row {
        QString item;
        QString restored;
        QString before;
        bool section = false;    ///< a heading row ("G functions", "Page 60", ...)
        bool collision = false;  ///< a collision of the way back (never a difference)
    };

  private:
    void buildRows(QVector<Row>& rows) const;
    void addVerification(QVector<Row>& rows) const;
    void addCollisions(QVector<Row>& rows) const;

    const RestartRun* run_;
    const RestartVerification* verification_;
    const RestartCollisions* collisions_;
    QVector<Row> all_;
    QVector<Row> shown_;
    bool differencesOnly_ = false;
};

}  // namespace mtc::screens
