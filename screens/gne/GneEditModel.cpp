#include "screens/gne/GneEditModel.h"

#include <QtGlobal>  // QT_TRANSLATE_NOOP only: the texts stay plain English strings
#include <algorithm>

#include "cnc_core/contour/GneText.h"
#include "screens/gne/GneEditSupport.h"

namespace mtc::screens {

namespace gne = mtc::core::gne;
using namespace gneedit;

namespace {

int lastLineOf(const gne::GneItem& item) {
    if (item.isContour) return static_cast<int>(std::max(item.contour.endLine, item.contour.line));
    return static_cast<int>(item.call.line);
}

int firstLineOf(const gne::GneItem& item) {
    return static_cast<int>(item.isContour ? item.contour.line : item.call.line);
}

/// Geometry number of a contour or form item, 0 for others.
int geometryNumber(const gne::GneItem& item) {
    if (item.isContour) return item.contour.number;
    if (item.call.keyword.rfind("FORM_", 0) == 0 && !item.call.values.empty() &&
        item.call.values[0])
        return static_cast<int>(*item.call.values[0]);
    return 0;
}

const gne::ContourSolution& emptySolution() {
    static const gne::ContourSolution none;
    return none;
}

}  // namespace

void GneEditModel::open(const std::string& programText, int line) {
    programLines_ = splitLines(programText);
    items_.clear();
    readProblems_.clear();
    usedNumbers_.clear();
    hasContextWindow_ = false;
    contextItems_.clear();
    contextPlane_ = gne::GnePlane::Turning;
    firstLine_ = lastLine_ = insertLine_ = 0;
    replaceEmptyLine_ = false;
    undo_.clear();
    redo_.clear();
    modified_ = false;
    current_ = 0;
    pickSection(programText, line);
    changed();
    selectLine(line);
}

void GneEditModel::selectLine(int line) {
    for (std::size_t row = 0; row < rows_.size(); ++row) {
        const gne::GneItem& item = items_[static_cast<std::size_t>(rows_[row].item)];
        int rowLine = static_cast<int>(item.call.line);
        if (item.isContour)
            rowLine = static_cast<int>(
                rows_[row].element < 0
                    ? item.contour.line
                    : item.contour.elements[static_cast<std::size_t>(rows_[row].element)].line);
        if (rowLine == line && line > 0) current_ = static_cast<int>(row);
    }
}

void GneEditModel::pickSection(const std::string& programText, int line) {
    const gne::GneDocument doc = gne::readGne(programText, 1);
    const int count = static_cast<int>(doc.items.size());
    int found = -1;
    for (int k = 0; k < count && found < 0; ++k) {
        const gne::GneItem& item = doc.items[static_cast<std::size_t>(k)];
        if (line == 0 || (firstLineOf(item) <= line && line <= lastLineOf(item))) found = k;
    }
    auto blankBetween = [&](int a, int b) {  // lines strictly between a and b
        for (int l = a + 1; l < b; ++l)
            if (!trimmed(programLines_[static_cast<std::size_t>(l - 1)]).empty()) return false;
        return true;
    };
    int first = found, last = found;
    if (found >= 0) {
        while (first > 0 && blankBetween(lastLineOf(doc.items[static_cast<std::size_t>(first - 1)]),
                                         firstLineOf(doc.items[static_cast<std::size_t>(first)])))
            --first;
        while (last + 1 < count &&
               blankBetween(lastLineOf(doc.items[static_cast<std::size_t>(last)]),
                            firstLineOf(doc.items[static_cast<std::size_t>(last) + 1])))
            ++last;
        firstLine_ = firstLineOf(doc.items[static_cast<std::size_t>(first)]);
        lastLine_ = lastLineOf(doc.items[static_cast<std::size_t>(last)]);
    } else {
        // A new call: an empty range before the first item at or after the line.
        insertLine_ = line <= 0 ? static_cast<int>(programLines_.size()) : line;
        first = count;
        for (int k = 0; k < count; ++k)
            if (firstLineOf(doc.items[static_cast<std::size_t>(k)]) >= insertLine_) {
                first = k;
                break;
            }
        last = first - 1;
    }
    for (int k = 0; k < count; ++k) {
        const gne::GneItem& item = doc.items[static_cast<std::size_t>(k)];
        if (k >= first && k <= last) {
            items_.push_back(item);
            continue;
        }
        if (const int n = geometryNumber(item)) usedNumbers_.push_back(n);
        if (k < first && !isCycle(item)) contextItems_.push_back(item);
        if (k < first && isWindow(item)) {
            contextWindow_ = item.call;
            hasContextWindow_ = true;
            contextPlane_ =
                item.call.keyword == "WINDOW_02" ? gne::GnePlane::Milling : gne::GnePlane::Turning;
        }
    }
    for (const gne::GneDiagnostic& d : doc.diagnostics)
        if (found >= 0 && static_cast<int>(d.line) >= firstLine_ &&
            static_cast<int>(d.line) <= lastLine_)
            readProblems_.push_back(d);
    if (found < 0) startNew(line);
}

void GneEditModel::startNew(int line) {
    const std::size_t index = static_cast<std::size_t>(std::max(line, 1) - 1);
    replaceEmptyLine_ = line > 0 && index < programLines_.size() &&
                        trimmed(programLines_[index]).empty() &&
                        !(index + 1 == programLines_.size());  // not the text's end
    if (!hasContextWindow_) {
        gne::GneItem window;
        window.call = gnefields::newCall("WINDOW_01", 0);
        items_.push_back(window);
    }
    gne::GneItem contour;
    contour.isContour = true;
    contour.contour.number = nextGeometryNumber();
    gne::ContourElement start;
    start.kind = gne::ElementKind::Start;
    start.end[0] = 0.0;
    start.end[1] = 0.0;
    contour.contour.elements.push_back(start);
    items_.push_back(contour);
}

int GneEditModel::nextGeometryNumber() const {
    int n = 1;
    auto used = [&](int k) {
        if (std::find(usedNumbers_.begin(), usedNumbers_.end(), k) != usedNumbers_.end())
            return true;
        for (const gne::GneItem& item : items_)
            if (geometryNumber(item) == k) return true;
        return false;
    };
    while (used(n))
        ++n;
    return n;
}

gne::GnePlane GneEditModel::planeOf(int item) const {
    gne::GnePlane plane = contextPlane_;
    for (int k = 0; k <= item && k < static_cast<int>(items_.size()); ++k)
        if (isWindow(items_[static_cast<std::size_t>(k)]))
            plane = items_[static_cast<std::size_t>(k)].call.keyword == "WINDOW_02"
                        ? gne::GnePlane::Milling
                        : gne::GnePlane::Turning;
    return plane;
}

gne::GneDocument GneEditModel::document(bool withContext) const {
    gne::GneDocument doc;
    if (withContext)  // the program's windows and geometry before the section
        doc.items = contextItems_;
    for (std::size_t i = 0; i < items_.size(); ++i) {
        gne::GneItem item = items_[i];
        const auto line = static_cast<std::uint32_t>(kLineBase + kItemStride * i);
        if (item.isContour) {
            item.contour.line = line;
            item.contour.endLine = line;
            item.contour.plane = planeOf(static_cast<int>(i));
            for (std::size_t j = 0; j < item.contour.elements.size(); ++j)
                item.contour.elements[j].line = line + static_cast<std::uint32_t>(j) + 1;
        } else {
            item.call.line = line;
        }
        doc.items.push_back(std::move(item));
    }
    return doc;
}

void GneEditModel::changed() {
    for (std::size_t i = 0; i < items_.size(); ++i)
        if (items_[i].isContour) items_[i].contour.plane = planeOf(static_cast<int>(i));
    const gne::GneDocument doc = document(true);
    solutions_.assign(items_.size(), gne::ContourSolution{});
    for (const gne::GneItem& item : doc.items) {
        if (!item.isContour || item.contour.line < kLineBase) continue;  // context
        const std::size_t i = (item.contour.line - kLineBase) / kItemStride;
        solutions_[i] = gne::solveContour(item.contour);
    }
    expansion_ = gne::expandGne(doc);
    buildRows();
}

void GneEditModel::buildRows() {
    rows_.clear();
    for (std::size_t i = 0; i < items_.size(); ++i) {
        rows_.push_back({static_cast<int>(i), -1});
        if (!items_[i].isContour) continue;
        for (std::size_t j = 0; j < items_[i].contour.elements.size(); ++j)
            rows_.push_back({static_cast<int>(i), static_cast<int>(j)});
    }
    current_ = std::clamp(current_, 0, std::max(0, static_cast<int>(rows_.size()) - 1));
}

void GneEditModel::setCurrentRow(int row) {
    if (row >= 0 && row < static_cast<int>(rows_.size())) current_ = row;
}

std::string GneEditModel::rowText(int row) const {
    if (row < 0 || row >= static_cast<int>(rows_.size())) return {};
    const GneRow r = rows_[static_cast<std::size_t>(row)];
    const gne::GneItem& item = items_[static_cast<std::size_t>(r.item)];
    if (!item.isContour) return gne::writeCall(item.call);
    if (r.element < 0)
        return "CONT (" + std::to_string(item.contour.number) +
               (item.contour.raw ? ", RAW)" : ", FINAL)");
    return "  " + gne::writeElement(item.contour.elements[static_cast<std::size_t>(r.element)],
                                    planeOf(r.item));
}

std::vector<gnefields::Field> GneEditModel::fields() const {
    if (rows_.empty()) return {};
    const GneRow r = rows_[static_cast<std::size_t>(current_)];
    const gne::GneItem& item = items_[static_cast<std::size_t>(r.item)];
    if (!item.isContour) return gnefields::callFields(item.call);
    if (r.element < 0) return gnefields::contourFields(item.contour);
    return gnefields::elementFields(item.contour.elements[static_cast<std::size_t>(r.element)],
                                    planeOf(r.item));
}

void GneEditModel::remember() {
    undo_.push_back({items_, current_});
    redo_.clear();
    modified_ = true;
}

bool GneEditModel::setField(int index, const std::string& text, gnefields::ModelText& message) {
    if (rows_.empty()) {
        message = {QT_TRANSLATE_NOOP("GneModel", "nothing selected")};
        return false;
    }
    const GneRow r = rows_[static_cast<std::size_t>(current_)];
    const Snapshot before{items_, current_};
    gne::GneItem& item = items_[static_cast<std::size_t>(r.item)];
    bool ok = false;
    if (!item.isContour)
        ok = gnefields::setCallField(item.call, index, text, message);
    else if (r.element < 0)
        ok = gnefields::setContourField(item.contour, index, text, message);
    else
        ok = gnefields::setElementField(item.contour.elements[static_cast<std::size_t>(r.element)],
                                        planeOf(r.item), index, text, message);
    if (!ok) return false;
    undo_.push_back(before);
    redo_.clear();
    modified_ = true;
    changed();
    return true;
}

int GneEditModel::currentContourItem() const {
    if (rows_.empty()) return -1;
    const GneRow r = rows_[static_cast<std::size_t>(current_)];
    return items_[static_cast<std::size_t>(r.item)].isContour ? r.item : -1;
}

gne::ContourElement* GneEditModel::currentElement() {
    if (rows_.empty()) return nullptr;
    const GneRow r = rows_[static_cast<std::size_t>(current_)];
    if (r.element < 0 || !items_[static_cast<std::size_t>(r.item)].isContour) return nullptr;
    return &items_[static_cast<std::size_t>(r.item)]
                .contour.elements[static_cast<std::size_t>(r.element)];
}

std::vector<std::string> GneEditModel::insertChoices() const {
    std::vector<std::string> choices;
    const int contour = currentContourItem();
    if (contour >= 0) {
        const auto& elements = items_[static_cast<std::size_t>(contour)].contour.elements;
        const bool hasStart = !elements.empty() && elements[0].kind == gne::ElementKind::Start;
        if (!hasStart) choices.push_back("START");
        for (const char* k : {"LINE", "CW", "CCW", "RD", "CF", "RELIEF"})
            choices.push_back(k);
    }
    const int item = rows_.empty() ? -1 : rows_[static_cast<std::size_t>(current_)].item;
    const bool turning = planeOf(item) == gne::GnePlane::Turning;
    choices.push_back("CONT");
    const std::vector<const char*> turningKeys = {"FORM_20", "CYCLE_10", "CYCLE_11", "CYCLE_12"};
    const std::vector<const char*> millingKeys = {"FORM_50", "FORM_51", "FORM_52",
                                                  "FORM_53", "FORM_54", "FORM_55",
                                                  "FORM_56", "FORM_57", "CYCLE_40"};
    for (const char* k : turning ? turningKeys : millingKeys)
        choices.push_back(k);
    choices.push_back("WINDOW_01");
    choices.push_back("WINDOW_02");
    return choices;
}

bool GneEditModel::insert(const std::string& choice, gnefields::ModelText& message) {
    static const std::vector<std::pair<std::string, gne::ElementKind>> kinds = {
        {"START", gne::ElementKind::Start},  {"LINE", gne::ElementKind::Line},
        {"CW", gne::ElementKind::ArcCW},     {"CCW", gne::ElementKind::ArcCCW},
        {"RD", gne::ElementKind::Round},     {"CF", gne::ElementKind::Chamfer},
        {"RELIEF", gne::ElementKind::Relief}};
    const std::vector<std::string> allowed = insertChoices();
    if (std::find(allowed.begin(), allowed.end(), choice) == allowed.end()) {
        message = {QT_TRANSLATE_NOOP("GneModel", "%1 cannot be inserted here"), {choice}};
        return false;
    }
    const GneRow r = rows_.empty() ? GneRow{-1, -1} : rows_[static_cast<std::size_t>(current_)];
    for (const auto& [name, kind] : kinds) {
        if (name != choice) continue;
        remember();
        auto& elements = items_[static_cast<std::size_t>(r.item)].contour.elements;
        gne::ContourElement e;
        e.kind = kind;
        if (kind == gne::ElementKind::Round) e.radius = 1.0;
        if (kind == gne::ElementKind::Chamfer) e.width = 1.0;
        const int at = kind == gne::ElementKind::Start ? 0 : r.element + 1;
        elements.insert(elements.begin() + at, e);
        changed();
        for (int row = 0; row < static_cast<int>(rows_.size()); ++row)
            if (rows_[static_cast<std::size_t>(row)].item == r.item &&
                rows_[static_cast<std::size_t>(row)].element == at)
                current_ = row;
        return true;
    }
    remember();
    gne::GneItem item;
    if (choice == "CONT") {
        item.isContour = true;
        item.contour.number = nextGeometryNumber();
        gne::ContourElement start;
        start.kind = gne::ElementKind::Start;
        item.contour.elements.push_back(start);
    } else {
        int number = choice.rfind("CYCLE_", 0) == 0 ? 0 : nextGeometryNumber();
        for (int k = std::min(r.item, static_cast<int>(items_.size()) - 1); k >= 0 && !number; --k)
            number = geometryNumber(items_[static_cast<std::size_t>(k)]);
        item.call = gnefields::newCall(choice, number > 0 ? number : 1);
    }
    const int at = r.item + 1;
    items_.insert(items_.begin() + at, item);
    changed();
    for (int row = 0; row < static_cast<int>(rows_.size()); ++row)
        if (rows_[static_cast<std::size_t>(row)].item == at &&
            rows_[static_cast<std::size_t>(row)].element == -1)
            current_ = row;
    return true;
}

bool GneEditModel::removeCurrent(gnefields::ModelText& message) {
    if (rows_.empty()) {
        message = {QT_TRANSLATE_NOOP("GneModel", "nothing to delete")};
        return false;
    }
    const GneRow r = rows_[static_cast<std::size_t>(current_)];
    remember();
    if (r.element >= 0) {
        auto& elements = items_[static_cast<std::size_t>(r.item)].contour.elements;
        elements.erase(elements.begin() + r.element);
    } else {
        items_.erase(items_.begin() + r.item);
    }
    current_ = std::max(0, current_ - 1);
    changed();
    return true;
}

int GneEditModel::alternativeCount() const {
    if (rows_.empty()) return 0;
    const GneRow r = rows_[static_cast<std::size_t>(current_)];
    if (r.element < 0) return 0;
    const auto& elements = solution(r.item).elements;
    if (r.element >= static_cast<int>(elements.size())) return 0;
    return static_cast<int>(elements[static_cast<std::size_t>(r.element)].candidates.size());
}

bool GneEditModel::nextAlternative() {
    const int count = alternativeCount();
    if (count < 2 || !currentElement()) return false;
    remember();
    gne::ContourElement* e = currentElement();
    e->alternative = (e->alternative + 1) % count;
    changed();
    return true;
}

bool GneEditModel::undo() {
    if (undo_.empty()) return false;
    redo_.push_back({items_, current_});
    items_ = undo_.back().items;
    current_ = undo_.back().current;
    undo_.pop_back();
    modified_ = true;
    changed();
    return true;
}

bool GneEditModel::redo() {
    if (redo_.empty()) return false;
    undo_.push_back({items_, current_});
    items_ = redo_.back().items;
    current_ = redo_.back().current;
    redo_.pop_back();
    modified_ = true;
    changed();
    return true;
}

const gne::ContourSolution& GneEditModel::solution(int item) const {
    if (item < 0 || item >= static_cast<int>(solutions_.size())) return emptySolution();
    return solutions_[static_cast<std::size_t>(item)];
}

bool GneEditModel::window(double& low0, double& low1, double& high0, double& high1) const {
    const gne::GneCall* window = hasContextWindow_ ? &contextWindow_ : nullptr;
    for (const gne::GneItem& item : items_)
        if (isWindow(item)) window = &item.call;
    if (!window) return false;
    auto v = [&](std::size_t i) {
        return i < window->values.size() && window->values[i] ? *window->values[i] : 0.0;
    };
    if (window->keyword == "WINDOW_01") {
        low0 = std::min(v(0), v(1)), high0 = std::max(v(0), v(1));
        low1 = v(3), high1 = v(2);
    } else {
        low0 = std::min(v(0), v(2)), high0 = std::max(v(0), v(2));
        low1 = std::min(v(1), v(3)), high1 = std::max(v(1), v(3));
    }
    return high0 > low0 && high1 > low1;
}

std::vector<gnefields::ModelText> GneEditModel::problemTexts() const {
    std::vector<gnefields::ModelText> texts;
    for (const gne::GneDiagnostic& d : readProblems_)
        texts.push_back({QT_TRANSLATE_NOOP("GneModel", "when read, line %1: %2"),
                         {std::to_string(d.line), d.message},
                         d.code});
    const std::vector<gnefields::ModelText> section = sectionProblemTexts();
    texts.insert(texts.end(), section.begin(), section.end());
    return texts;
}

std::vector<gnefields::ModelText> GneEditModel::sectionProblemTexts() const {
    std::vector<gnefields::ModelText> texts;
    for (std::size_t row = 0; row < rows_.size(); ++row) {  // the start point is given
        const gne::GneItem& item = items_[static_cast<std::size_t>(rows_[row].item)];
        if (!item.isContour || rows_[row].element >= 0) continue;
        const auto& e = item.contour.elements;
        if (e.empty() || e[0].kind != gne::ElementKind::Start || !e[0].end[0] || !e[0].end[1])
            texts.push_back(
                {QT_TRANSLATE_NOOP("GneModel",
                                   "row %1 (%2): the contour needs a START with both coordinates"),
                 {std::to_string(row + 1), rowText(static_cast<int>(row))}});
    }
    for (const gne::GneDiagnostic& d : expansion_.diagnostics) {
        if (d.line < kLineBase) continue;  // the program's other instructions
        const std::uint32_t item = (d.line - kLineBase) / kItemStride;
        const std::uint32_t element = (d.line - kLineBase) % kItemStride;
        int row = 0;
        for (std::size_t k = 0; k < rows_.size(); ++k)
            if (rows_[k].item == static_cast<int>(item) &&
                rows_[k].element == static_cast<int>(element) - 1)
                row = static_cast<int>(k);
        texts.push_back({QT_TRANSLATE_NOOP("GneModel", "row %1 (%2): %3"),
                         {std::to_string(row + 1), trimmed(rowText(row)), d.message},
                         d.code});
    }
    return texts;
}

}  // namespace mtc::screens
