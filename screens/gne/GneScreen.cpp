#include "screens/gne/GneScreen.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QTableWidget>
#include <QVBoxLayout>

#include "hmi/CellSession.h"
#include "hmi/ProgramWorkspace.h"
#include "screens/gne/GneCanvas.h"
#include "screens/gne/GneTexts.h"

namespace mtc::screens {

namespace {
const QString kEditorScreen = "editor";
const char* kExitKeywords = QT_TRANSLATE_NOOP("mtc::screens::GneScreen",
                                              "Save as function call (keywords with parameters)");
const char* kExitBlocks =
    QT_TRANSLATE_NOOP("mtc::screens::GneScreen", "Save as NC blocks (expanded)");
const char* kExitDiscard = QT_TRANSLATE_NOOP("mtc::screens::GneScreen", "Discard the changes");

QString q(const std::string& s) {
    return QString::fromStdString(s);
}
}  // namespace

GneScreen::GneScreen(const mtc::hmi::ScreenContext& context,
                     std::shared_ptr<mtc::hmi::ProgramWorkspace> workspace)
    : Screen(context), workspace_(std::move(workspace)) {
    heading_ = new QLabel(this);
    heading_->setObjectName("gneHeading");
    rows_ = new QListWidget(this);
    rows_->setObjectName("gneRows");
    rows_->setFont(QFont("Monospace"));
    rows_->installEventFilter(this);
    fields_ = new QTableWidget(0, 2, this);
    fields_->setObjectName("gneFields");
    fields_->setHorizontalHeaderLabels({tr("Name"), tr("Value")});
    fields_->verticalHeader()->hide();
    fields_->horizontalHeader()->setStretchLastSection(true);
    fields_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    fields_->setSelectionBehavior(QAbstractItemView::SelectRows);
    fields_->setSelectionMode(QAbstractItemView::SingleSelection);
    fields_->installEventFilter(this);
    fieldHelp_ = new QLabel(this);
    fieldHelp_->setObjectName("gneFieldHelp");
    fieldHelp_->setWordWrap(true);
    input_ = new QLineEdit(this);
    input_->setObjectName("gneInput");
    input_->installEventFilter(this);
    choices_ = new QListWidget(this);
    choices_->setObjectName("gneChooser");
    choices_->installEventFilter(this);
    problems_ = new QLabel(this);
    problems_->setObjectName("gneProblems");
    problems_->setWordWrap(true);
    problems_->setStyleSheet("color: #a00000;");
    message_ = new QLabel(this);
    message_->setObjectName("gneMessage");
    message_->setWordWrap(true);
    canvas_ = new GneCanvas(&model_, this);

    auto* left = new QVBoxLayout;
    left->addWidget(rows_, 3);
    left->addWidget(choices_, 3);
    left->addWidget(fields_, 2);
    left->addWidget(fieldHelp_);
    left->addWidget(input_);
    auto* middle = new QHBoxLayout;
    middle->addLayout(left, 2);
    middle->addWidget(canvas_, 3);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(heading_);
    layout->addLayout(middle, 1);
    layout->addWidget(problems_);
    layout->addWidget(message_);
    setFocusProxy(rows_);
    choices_->hide();
    closeInput();
    connect(rows_, &QListWidget::currentRowChanged, this, [this](int row) {
        if (row < 0 || row == model_.currentRow()) return;
        model_.setCurrentRow(row);
        refreshFields();
        canvas_->update();
        emit softKeysChanged();
    });
    connect(fields_, &QTableWidget::currentCellChanged, this, [this](int row, int, int, int) {
        const auto fields = model_.fields();
        fieldHelp_->setText(row >= 0 && row < static_cast<int>(fields.size())
                                ? gneMeaning(fields[static_cast<std::size_t>(row)])
                                : QString());
    });
}

void GneScreen::activated() {
    // Normally the editor's request; called directly (menu, --screen gne):
    // the selected program's first GNE section.
    int wanted = workspace_->editProgram();
    const int line = wanted == 0 ? 0 : workspace_->editLine();
    if (wanted == 0) wanted = context().session->control(context().process).selectedProgram();
    const auto program = context().session->program(context().process, wanted);
    if (!program) {
        program_ = 0;
        showMessage(tr("Open the GNE from the program editor (GNE soft key on a line)"), true);
        refresh();
        return;
    }
    if (wanted != program_ || line != openedLine_ || program.get() != openedSource_)
        openOn(wanted, program->source.str(), line);
    openedSource_ = program.get();
    rows_->setFocus();
}

void GneScreen::openOn(int number, const std::string& programText, int line) {
    program_ = number;
    openedLine_ = line;
    openedSource_ = nullptr;
    model_.open(programText, line);
    closeChooser();
    closeInput();
    canvas_->setZoomToWindow(true);
    showMessage(model_.isNew() ? tr("New GNE section before line %1").arg(model_.spliceLine())
                               : tr("Modifying the GNE section of lines %1-%2")
                                     .arg(model_.firstLine())
                                     .arg(model_.lastLine()));
    refresh();
}

void GneScreen::refresh() {
    heading_->setText(
        tr("GNE  program %1  %2%3")
            .arg(program_, 3, 10, QChar('0'))
            .arg(model_.isNew() ? tr("new section at line %1").arg(model_.spliceLine())
                                : tr("lines %1-%2").arg(model_.firstLine()).arg(model_.lastLine()))
            .arg(model_.modified() ? "  " + tr("*modified*") : QString()));
    const QSignalBlocker block(rows_);
    rows_->clear();
    for (int row = 0; row < static_cast<int>(model_.rows().size()); ++row)
        rows_->addItem(q(model_.rowText(row)));
    rows_->setCurrentRow(model_.currentRow());
    refreshFields();
    problems_->setText(gneLines(model_.problemTexts()));
    canvas_->update();
    emit softKeysChanged();
}

void GneScreen::refreshFields() {
    const int keep = std::max(0, fields_->currentRow());
    const auto fields = model_.fields();
    fields_->setRowCount(static_cast<int>(fields.size()));
    for (int i = 0; i < static_cast<int>(fields.size()); ++i) {
        const auto& f = fields[static_cast<std::size_t>(i)];
        fields_->setItem(i, 0, new QTableWidgetItem(q(f.name) + (f.required ? " *" : "")));
        fields_->setItem(i, 1, new QTableWidgetItem(f.value.empty() ? "?" : q(f.value)));
        fields_->item(i, 0)->setToolTip(gneMeaning(f));
    }
    if (!fields.empty()) fields_->setCurrentCell(std::min(keep, fields_->rowCount() - 1), 1);
}

void GneScreen::showMessage(const QString& text, bool error) {
    message_->setText(text);
    message_->setStyleSheet(error ? "color: #a00000;" : "");
}

bool GneScreen::eventFilter(QObject* watched, QEvent* event) {
    const bool ownEscape = watched == fields_ || watched == input_ || watched == choices_;
    if (event->type() == QEvent::ShortcutOverride && ownEscape &&
        static_cast<QKeyEvent*>(event)->key() == Qt::Key_Escape) {
        event->accept();  // Esc steps back inside the dialog, not to the menu
        return true;
    }
    if (event->type() != QEvent::KeyPress) return Screen::eventFilter(watched, event);
    const auto* key = static_cast<QKeyEvent*>(event);
    if (watched == rows_) return rowKey(key->key(), key->modifiers());
    if (watched == fields_) return fieldKey(key->key(), key->text());
    if (watched == input_) return inputKey(key->key());
    if (watched == choices_) return chooserKey(key->key());
    return Screen::eventFilter(watched, event);
}

bool GneScreen::rowKey(int key, Qt::KeyboardModifiers modifiers) {
    if (modifiers & Qt::ControlModifier) {
        if (key == Qt::Key_Z) return undo(), true;
        if (key == Qt::Key_Y) return redo(), true;
        return false;
    }
    switch (key) {
        case Qt::Key_Return:
        case Qt::Key_Enter:
        case Qt::Key_Right:
            if (fields_->rowCount() > 0) {
                fields_->setFocus();
                fields_->setCurrentCell(0, 1);
            }
            return true;
        case Qt::Key_Insert:
            openChooser(Chooser::Insert);
            return true;
        case Qt::Key_Delete:
            deleteRow();
            return true;
        case Qt::Key_Plus:
            canvas_->zoomBy(1.5);
            return true;
        case Qt::Key_Minus:
            canvas_->zoomBy(1 / 1.5);
            return true;
        default:
            return false;
    }
}

bool GneScreen::fieldKey(int key, const QString& text) {
    switch (key) {
        case Qt::Key_Return:
        case Qt::Key_Enter: {
            const QTableWidgetItem* value = fields_->item(fields_->currentRow(), 1);
            if (value) startInput(value->text() == "?" ? QString() : value->text());
            return true;
        }
        case Qt::Key_Escape:
        case Qt::Key_Left:
            rows_->setFocus();
            return true;
        case Qt::Key_Delete:
            clearField();
            return true;
        default:
            break;
    }
    // Typing a value starts the entry with that character.
    if (text.size() == 1 &&
        (text[0].isDigit() || text[0] == '-' || text[0] == '.' || text[0].isLetter())) {
        startInput(text);
        return true;
    }
    return false;
}

bool GneScreen::inputKey(int key) {
    if (key == Qt::Key_Return || key == Qt::Key_Enter) {
        applyInput();
        return true;
    }
    if (key == Qt::Key_Escape) {
        closeInput();
        showMessage(tr("Entry cancelled, value unchanged"));
        return true;
    }
    return false;
}

void GneScreen::startInput(const QString& initial) {
    if (fields_->currentRow() < 0) return;
    input_->setText(initial);
    input_->setEnabled(true);
    input_->setFocus();
    showMessage(tr("Enter %1 (Enter takes it, Esc cancels, empty = not given)")
                    .arg(fields_->item(fields_->currentRow(), 0)->text()));
}

void GneScreen::applyInput() {
    const int index = fields_->currentRow();
    gnefields::ModelText error;
    if (!model_.setField(index, input_->text().toStdString(), error)) {
        showMessage(tr("%1 - the old value is kept").arg(gneText(error)), true);
        input_->selectAll();
        return;  // the entry stays open for a correction
    }
    closeInput();
    refresh();
    const int next = std::min(index + 1, fields_->rowCount() - 1);
    fields_->setFocus();
    fields_->setCurrentCell(next, 1);
    showMessage(tr("Value taken"));
}

void GneScreen::closeInput() {
    input_->clear();
    input_->setEnabled(false);
    if (input_->hasFocus() || focusWidget() == input_) fields_->setFocus();
}

void GneScreen::clearField() {
    gnefields::ModelText error;
    if (!model_.setField(fields_->currentRow(), "", error)) {
        showMessage(tr("%1 - the old value is kept").arg(gneText(error)), true);
        return;
    }
    const int row = fields_->currentRow();
    refresh();
    fields_->setFocus();
    fields_->setCurrentCell(row, 1);
    showMessage(tr("Value cleared: the solver computes it"));
}

void GneScreen::openChooser(Chooser kind) {
    chooser_ = kind;
    choices_->clear();
    if (kind == Chooser::Insert) {
        for (const std::string& c : model_.insertChoices())
            choices_->addItem(q(c));
        showMessage(tr("Insert after the selected row: Up/Down, Enter; Esc = back"));
    } else {
        choices_->addItems({tr(kExitKeywords), tr(kExitBlocks), tr(kExitDiscard)});
        showMessage(tr("How shall the section go into the program? Up/Down, Enter; Esc = back"));
    }
    choices_->setCurrentRow(0);
    choices_->show();
    choices_->setFocus();
    emit softKeysChanged();
}

void GneScreen::closeChooser() {
    chooser_ = Chooser::None;
    choices_->hide();
    rows_->setFocus();
    emit softKeysChanged();
}

bool GneScreen::chooserKey(int key) {
    if (key == Qt::Key_Escape) {
        closeChooser();
        showMessage("");
        return true;
    }
    if (key == Qt::Key_Return || key == Qt::Key_Enter) {
        choose();
        return true;
    }
    return false;
}

void GneScreen::choose() {
    const QListWidgetItem* item = choices_->currentItem();
    if (!item) return;
    const QString choice = item->text();
    const Chooser kind = chooser_;
    closeChooser();
    if (kind == Chooser::Insert) return insertChoice(choice.toStdString());
    if (choice == tr(kExitKeywords)) return finish(GneOutput::FunctionCall);
    if (choice == tr(kExitBlocks)) return finish(GneOutput::NcBlocks);
    discard();
}

void GneScreen::insertChoice(const std::string& choice) {
    gnefields::ModelText error;
    if (!model_.insert(choice, error)) return showMessage(gneText(error), true);
    refresh();
    showMessage(tr("%1 inserted: enter its values (Enter)").arg(q(choice)));
}

void GneScreen::deleteRow() {
    gnefields::ModelText error;
    if (!model_.removeCurrent(error)) return showMessage(gneText(error), true);
    refresh();
    showMessage(tr("Row deleted (Undo: F4 or Ctrl+Z)"));
}

void GneScreen::nextAlternative() {
    if (!model_.nextAlternative()) {
        showMessage(tr("The selected element has no other solution"), true);
        return;
    }
    refresh();
    const auto& row = model_.rows()[static_cast<std::size_t>(model_.currentRow())];
    const auto& e = model_.items()[static_cast<std::size_t>(row.item)]
                        .contour.elements[static_cast<std::size_t>(row.element)];
    showMessage(
        tr("Solution %1 of %2 chosen").arg(e.alternative + 1).arg(model_.alternativeCount()));
}

void GneScreen::undo() {
    if (model_.undo()) refresh(), showMessage(tr("Undone"));
}

void GneScreen::redo() {
    if (model_.redo()) refresh(), showMessage(tr("Redone"));
}

void GneScreen::toggleZoom() {
    canvas_->setZoomToWindow(!canvas_->zoomToWindow());
    emit softKeysChanged();
}

void GneScreen::finish(GneOutput output) {
    if (program_ == 0) return showMessage(tr("No program: open the GNE from the editor"), true);
    if (output == GneOutput::FunctionCall) {
        const std::vector<gnefields::ModelText> open = model_.sectionProblemTexts();
        if (!open.empty())
            return showMessage(
                tr("Not saved - the section is not complete: %1").arg(gneText(open.front())), true);
    }
    std::string text;
    gnefields::ModelText problem;
    if (!model_.output(output, text, problem)) return showMessage(gneText(problem), true);
    QString error;
    if (!workspace_->save(program_, q(model_.splice(text)), error)) return showMessage(error, true);
    workspace_->requestEdit(program_, model_.spliceLine());
    openedLine_ = -1;  // the next GNE call opens afresh
    emit navigateTo(kEditorScreen);
}

void GneScreen::discard() {
    openedLine_ = -1;
    workspace_->requestEdit(program_, model_.spliceLine());
    emit navigateTo(kEditorScreen);
}

mtc::hmi::SoftKeys GneScreen::softKeys() {
    mtc::hmi::SoftKeys keys(8);
    const bool open = program_ != 0 && chooser_ == Chooser::None;
    keys[0] = {tr("Insert\nIns"), [this] { openChooser(Chooser::Insert); }, open};
    keys[1] = {tr("Delete\nrow"), [this] { deleteRow(); }, open && !model_.rows().empty()};
    keys[2] = {tr("Alter-\nnative"), [this] { nextAlternative(); },
               open && model_.alternativeCount() > 1};
    keys[3] = {tr("Undo"), [this] { undo(); }, open && model_.canUndo()};
    keys[4] = {tr("Redo"), [this] { redo(); }, open && model_.canRedo()};
    keys[5] = {canvas_->zoomToWindow() ? tr("Zoom\ncontour") : tr("Zoom\nwindow"),
               [this] { toggleZoom(); }};
    keys[6] = {tr("Edit\nvalue"),
               [this] {
                   fields_->setFocus();
                   fieldKey(Qt::Key_Return, QString());
               },
               open && fields_->rowCount() > 0};
    keys[7] = {tr("Exit"), [this] { openChooser(Chooser::Exit); }, open};
    return keys;
}

}  // namespace mtc::screens
