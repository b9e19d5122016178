#include "screens/tooldata/ToolTableModel.h"

#include "cnc_core/tooldata/DataFileText.h"

namespace mtc::screens {

namespace {

struct ColumnInfo {
    const char* header;
    const char* key;
    const char* meaning;
    int decimals;
};

// Headers short enough for the panel's minimum width; the meaning goes
// into the prompt.
const ColumnInfo kColumns[ToolTableModel::ColumnCount] = {
    {QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "T"), "",
     QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "tool number"), 0},
    {QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "Name"), "name",
     QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "name"), 0},
    {QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "E"), "",
     QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "cutting edge"), 0},
    {QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "R"), "radius",
     QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "radius R"), 3},
    {QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "R\nwear"), "radius_wear",
     QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "wear of R"), 3},
    {QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "L1"), "l1",
     QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "length L1"), 3},
    {QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "L1\nwear"), "l1_wear",
     QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "wear of L1"), 3},
    {QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "L2"), "l2",
     QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "length L2"), 3},
    {QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "L2\nwear"), "l2_wear",
     QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "wear of L2"), 3},
    {QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "L3"), "l3",
     QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "length L3"), 3},
    {QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "L3\nwear"), "l3_wear",
     QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "wear of L3"), 3},
    {QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "Pos"), "orientation",
     QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "cutting edge position"), 0},
    {QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "Corner"), "corner_angle",
     QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "corner angle"), 1},
    {QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "Setting"), "setting_angle",
     QT_TRANSLATE_NOOP("mtc::screens::ToolTableModel", "setting angle"), 1},
};

}  // namespace

ToolTableModel::ToolTableModel(std::shared_ptr<const mtc::core::ToolList> list, QObject* parent)
    : CursorTableModel(parent), list_(std::move(list)) {
    readRows();
}

void ToolTableModel::readRows() {
    rows_.clear();
    if (!list_) return;
    for (const mtc::core::Tool& tool : list_->tools())
        for (const mtc::core::ToolEdge& edge : tool.edges)
            rows_.push_back({tool.number, edge.edge});
}

void ToolTableModel::refresh() {
    const int tool = currentTool(), edge = currentEdge();
    beginResetModel();
    readRows();
    keepCursorInside();
    endResetModel();
    showEdge(tool, edge);
}

void ToolTableModel::showEdge(int tool, int edge) {
    for (std::size_t row = 0; row < rows_.size(); ++row) {
        if (rows_[row].tool != tool || (edge != 0 && rows_[row].edge != edge)) continue;
        setCursor(static_cast<int>(row), cursorColumn());
        return;
    }
    setCursor(cursorRow(), cursorColumn());  // the nearest row that is left
}

int ToolTableModel::currentTool() const {
    return rows_.empty() ? 0 : rows_[static_cast<std::size_t>(cursorRow())].tool;
}

int ToolTableModel::currentEdge() const {
    return rows_.empty() ? 0 : rows_[static_cast<std::size_t>(cursorRow())].edge;
}

const char* ToolTableModel::columnKey(int column) {
    return column >= 0 && column < ColumnCount ? kColumns[column].key : "";
}

QString ToolTableModel::columnMeaning(int column) {
    return column >= 0 && column < ColumnCount ? tr(kColumns[column].meaning) : QString();
}

double ToolTableModel::value(const mtc::core::ToolEdge& e, int column) {
    switch (column) {
        case Radius:
            return e.radius;
        case RadiusWear:
            return e.radiusWear;
        case Length1:
            return e.length1;
        case Length1Wear:
            return e.length1Wear;
        case Length2:
            return e.length2;
        case Length2Wear:
            return e.length2Wear;
        case Length3:
            return e.length3;
        case Length3Wear:
            return e.length3Wear;
        case Orientation:
            return e.orientation;
        case CornerAngle:
            return e.cornerAngle;
        case SettingAngle:
            return e.settingAngle;
        default:
            return 0.0;
    }
}

QString ToolTableModel::currentValueText() const {
    if (rows_.empty() || !list_) return {};
    const Row& row = rows_[static_cast<std::size_t>(cursorRow())];
    const mtc::core::Tool* tool = list_->find(row.tool);
    const mtc::core::ToolEdge* edge = tool ? tool->edge(row.edge) : nullptr;
    if (!edge) return {};
    if (cursorColumn() == Name) return QString::fromStdString(tool->name);
    if (cursorColumn() == Tool || cursorColumn() == Edge) return {};
    return QString::fromStdString(mtc::core::formatDataNumber(value(*edge, cursorColumn())));
}

QString ToolTableModel::cellText(int rowIndex, int column) const {
    if (rowIndex < 0 || static_cast<std::size_t>(rowIndex) >= rows_.size() || !list_) return {};
    const Row& row = rows_[static_cast<std::size_t>(rowIndex)];
    const mtc::core::Tool* tool = list_->find(row.tool);
    const mtc::core::ToolEdge* edge = tool ? tool->edge(row.edge) : nullptr;
    if (!edge) return {};
    switch (column) {
        case Tool:
            return QString("T%1").arg(row.tool);
        case Name:
            return QString::fromStdString(tool->name);
        case Edge:
            return QString("E%1").arg(row.edge);
        default:
            return tableNumber(value(*edge, column), kColumns[column].decimals);
    }
}

int ToolTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(rows_.size());
}

int ToolTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant ToolTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (role != Qt::DisplayRole || orientation != Qt::Horizontal || section < 0 ||
        section >= ColumnCount)
        return {};
    return tr(kColumns[section].header);
}

}  // namespace mtc::screens
