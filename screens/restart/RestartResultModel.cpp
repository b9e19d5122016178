#include "screens/restart/RestartResultModel.h"

#include <QBrush>
#include <QColor>
#include <QFont>

#include "cnc_core/interp/ModalGroups.h"
#include "hmi/PanelLanguage.h"
#include "screens/restart/RestartCollisions.h"
#include "screens/restart/RestartRun.h"
#include "screens/restart/RestartVerification.h"

namespace mtc::screens {

namespace {

QString groupName(int group) {
    switch (group) {
        case mtc::core::kGroupInterpolation:
            return RestartResultModel::tr("interpolation");
        case mtc::core::kGroupPlane:
            return RestartResultModel::tr("plane");
        case mtc::core::kGroupToolPath:
            return RestartResultModel::tr("tool path compensation");
        case mtc::core::kGroupZeroOffset:
            return RestartResultModel::tr("zero offset");
        case mtc::core::kGroupFeedType:
            return RestartResultModel::tr("feed type");
        case mtc::core::kGroupDimension:
            return RestartResultModel::tr("dimension");
        case mtc::core::kGroupRadiusDiameter:
            return RestartResultModel::tr("radius / diameter");
        case mtc::core::kGroupUnits:
            return RestartResultModel::tr("units");
        case mtc::core::kGroupSurfaceSpeed:
            return RestartResultModel::tr("surface speed");
        case mtc::core::kGroupToolLength:
            return RestartResultModel::tr("tool length compensation");
        case mtc::core::kGroupTransformation:
            return RestartResultModel::tr("transformation");
        default:
            return "";
    }
}

QString function(char letter, int value) {
    return value < 0 ? RestartResultModel::tr("none (−1)") : QString("%1%2").arg(letter).arg(value);
}

QString number(double value) {
    return QString::number(value, 'g', 10);
}

QString buffer(const std::array<int, 40>& elements, int count) {
    if (count == 0) return RestartResultModel::tr("empty");
    QStringList list;
    for (int i = 0; i < count; ++i)
        list << QString::number(elements[static_cast<std::size_t>(i)]);
    return QString("%1: %2").arg(count).arg(list.join(' '));
}

}  // namespace

RestartResultModel::RestartResultModel(const RestartRun* run,
                                       const RestartVerification* verification,
                                       const RestartCollisions* collisions, QObject* parent)
    : QAbstractTableModel(parent),
      run_(run),
      verification_(verification),
      collisions_(collisions) {}

namespace {

/// Adds a row (item, value at the target, value before the restart).
void addRow(QVector<RestartResultModel::Row>& rows, const QString& item, const QString& restored,
            const QString& before) {
    rows.push_back({item, restored, before, false});
}

void addSection(QVector<RestartResultModel::Row>& rows, const QString& title) {
    rows.push_back({title, {}, {}, true});
}

void addGFunctions(QVector<RestartResultModel::Row>& rows, const mtc::core::InterpreterState& at,
                   const mtc::core::InterpreterState& before) {
    addSection(rows, RestartResultModel::tr("G functions (modal groups)"));
    for (int group : mtc::core::usedGGroups()) {
        const auto g = static_cast<std::size_t>(group);
        addRow(rows,
               RestartResultModel::tr("G group %1 %2").arg(group).arg(groupName(group)).trimmed(),
               function('G', at.modal.g[g]), function('G', before.modal.g[g]));
    }
}

void addAuxiliary(QVector<RestartResultModel::Row>& rows, const mtc::core::InterpreterState& at,
                  const mtc::core::InterpreterState& before) {
    addSection(rows, RestartResultModel::tr("Auxiliary functions"));
    for (int group = 1; group <= 15; ++group) {
        const auto m = static_cast<std::size_t>(group);
        addRow(rows, RestartResultModel::tr("M group %1").arg(group), function('M', at.mGroups[m]),
               function('M', before.mGroups[m]));
    }
    addRow(rows, RestartResultModel::tr("M(16), last output"), function('M', at.mGroups[16]),
           function('M', before.mGroups[16]));
    addRow(rows, RestartResultModel::tr("Q, last output"), function('Q', at.lastQ),
           function('Q', before.lastQ));
    for (int s = 1; s < mtc::core::kSpindleSlots; ++s) {
        const auto i = static_cast<std::size_t>(s);
        addRow(rows, RestartResultModel::tr("S%1 speed").arg(s), number(at.modal.spindleSpeed[i]),
               number(before.modal.spindleSpeed[i]));
    }
    addRow(rows, RestartResultModel::tr("T (tool)"), QString::number(at.modal.tool),
           QString::number(before.modal.tool));
    addRow(rows, "E", QString::number(at.modal.edge), QString::number(before.modal.edge));
    addRow(rows, RestartResultModel::tr("D (correction)"), QString::number(at.modal.correction),
           QString::number(before.modal.correction));
    addRow(rows, RestartResultModel::tr("F (feed)"), number(at.modal.feed),
           number(before.modal.feed));
}

void addPage60(QVector<RestartResultModel::Row>& rows, const mtc::core::InterpreterState& at,
               const mtc::core::InterpreterState& before) {
    addSection(rows, RestartResultModel::tr("Page 60 (restart and REPOS)"));
    for (int s = 1; s < mtc::core::kSpindleSlots; ++s) {
        const auto i = static_cast<std::size_t>(s);
        addRow(rows, RestartResultModel::tr("Rotary axis mode S%1").arg(s),
               QString::number(at.modal.rotaryAxisMode[i]),
               QString::number(before.modal.rotaryAxisMode[i]));
    }
    const auto t = static_cast<std::size_t>(mtc::core::kGroupTransformation);
    addRow(rows, RestartResultModel::tr("Transformation selection"), QString::number(at.modal.g[t]),
           QString::number(before.modal.g[t]));
    for (int s = 0; s < mtc::core::kToolSpindles; ++s) {
        const auto i = static_cast<std::size_t>(s);
        addRow(rows, RestartResultModel::tr("T in tool spindle %1").arg(s + 1),
               QString::number(at.modal.toolSpindle[i]),
               QString::number(before.modal.toolSpindle[i]));
    }
}

}  // namespace

void RestartResultModel::addCollisions(QVector<Row>& rows) const {
    const QString summary = collisions_->summary();
    if (summary.isEmpty()) return;
    addSection(rows, RestartResultModel::tr("Way back against the part (ADJUST / REPOS)"));
    const auto& result = collisions_->result();
    if (!collisions_->colliding()) {
        addRow(rows, summary, {}, {});
        return;
    }
    for (std::size_t i = 0; i < result->collisions.size(); ++i)
        rows.push_back({collisions_->where(i) + ": " + collisions_->what(i),
                        collisions_->position(i), QString("—"), false, true});
}

void RestartResultModel::buildRows(QVector<Row>& rows) const {
    const mtc::core::ComputingProcess& computing = run_->sequence().computing();
    addCollisions(rows);
    addGFunctions(rows, computing.state(), run_->before());
    addAuxiliary(rows, computing.state(), run_->before());
    addPage60(rows, computing.state(), run_->before());
    addSection(rows, RestartResultModel::tr("Page 61 buffers, oldest first"));
    const mtc::core::RestartAuxCollector& collector = computing.collector();
    addRow(rows, RestartResultModel::tr("M(16) buffer"),
           buffer(collector.m16().elements(), collector.m16().size()), "—");
    addRow(rows, RestartResultModel::tr("Q buffer"),
           buffer(collector.q().elements(), collector.q().size()), "—");
    addVerification(rows);
}

void RestartResultModel::addVerification(QVector<Row>& rows) const {
    // The same comparison as `mtc200-cli verify-restart` (restart.md R-028):
    // at the target: expected (the normal run); other column: what the
    // computing process computed, or what ADJUST and REPOS will leave.
    addSection(rows, RestartResultModel::tr(
                         "Verification: normal run vs. computing process, ADJUST and REPOS"));
    const auto& target = verification_->target();
    if (!target) {
        addRow(rows, RestartResultModel::tr("Not verified yet"), QString("F4"), QString("F4"));
        return;
    }
    using mtc::core::TargetOutcome;
    if (target->outcome == TargetOutcome::Failed ||
        target->outcome == TargetOutcome::NotSelectable) {
        QString why = RestartResultModel::tr("the restart fails");
        for (const auto& d : target->diagnostics.items())
            if (d.severity == mtc::core::Severity::Error) {
                why = QString::fromStdString(d.code) + ": " + hmi::coreMessageLine(d);
                break;
            }
        addRow(rows, RestartResultModel::tr("Verification"), why, QString("—"));
        return;
    }
    if (target->outcome == TargetOutcome::Reestablished) {
        addRow(rows, RestartResultModel::tr("Every item"), RestartResultModel::tr("re-established"),
               RestartResultModel::tr("re-established"));
        return;
    }
    for (const auto& d : target->computed)
        addRow(rows,
               RestartResultModel::tr("Computing process: %1").arg(QString::fromStdString(d.label)),
               QString::fromStdString(d.expectedText), QString::fromStdString(d.actualText));
    for (const auto& d : target->cutting)
        addRow(
            rows,
            RestartResultModel::tr("After ADJUST / REPOS: %1").arg(QString::fromStdString(d.label)),
            QString::fromStdString(d.expectedText), QString::fromStdString(d.actualText));
}

QString RestartResultModel::verificationSummary() const {
    const auto& target = verification_->target();
    if (!target) return RestartResultModel::tr("not verified yet");
    using mtc::core::TargetOutcome;
    switch (target->outcome) {
        case TargetOutcome::Reestablished:
            return RestartResultModel::tr("re-established");
        case TargetOutcome::Differs:
            return RestartResultModel::tr("%1 differences")
                .arg(static_cast<int>(target->computed.size() + target->cutting.size()));
        case TargetOutcome::Failed:
        case TargetOutcome::NotSelectable:
            return RestartResultModel::tr("the restart fails");
    }
    return {};
}

void RestartResultModel::reload() {
    beginResetModel();
    all_.clear();
    if (run_->started()) buildRows(all_);
    shown_.clear();
    for (const Row& row : all_)
        if (!differencesOnly_ || row.section || row.collision || row.restored != row.before)
            shown_.push_back(row);
    endResetModel();
}

void RestartResultModel::setDifferencesOnly(bool only) {
    differencesOnly_ = only;
    reload();
}

int RestartResultModel::differenceCount() const {
    int count = 0;
    for (const Row& row : all_)
        if (!row.section && !row.collision && row.restored != row.before) ++count;
    return count;
}

int RestartResultModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : shown_.size();
}

int RestartResultModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : 3;
}

QVariant RestartResultModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= shown_.size()) return {};
    const Row& row = shown_[index.row()];
    const bool differs = !row.section && !row.collision && row.restored != row.before;
    switch (role) {
        case Qt::DisplayRole:
            return index.column() == 0 ? row.item : index.column() == 1 ? row.restored : row.before;
        case DiffersRole:
            return differs;
        case CollisionRole:
            return row.collision;
        case SectionRole:
            return row.section;
        case Qt::ToolTipRole:  // the whole collision, where and what, on one line
            return row.collision ? row.item + " — " + row.restored : QVariant();
        case Qt::BackgroundRole:
            if (row.section) return QBrush(QColor(0xdf, 0xe6, 0xef));
            if (row.collision) return QBrush(QColor(0xff, 0xd4, 0xd4));
            return differs ? QBrush(QColor(0xff, 0xe8, 0x90)) : QVariant();
        case Qt::ForegroundRole:
            return row.collision ? QBrush(QColor(0xb0, 0x00, 0x00)) : QVariant();
        case Qt::FontRole: {
            if (!row.section && !differs && !row.collision) return {};
            QFont font;
            font.setBold(true);
            return font;
        }
        default:
            return {};
    }
}

QVariant RestartResultModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
        case 0:
            return RestartResultModel::tr("Item");
        case 1:
            return RestartResultModel::tr("At the target");
        case 2:
            return RestartResultModel::tr("Machine before");
        default:
            return {};
    }
}

}  // namespace mtc::screens
