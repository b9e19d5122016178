#include "screens/tooldata/ToolTableScreen.h"

#include <QTableView>

#include "cnc_core/tooldata/SetupDataEditor.h"
#include "cnc_core/tooldata/ToolListFile.h"
#include "hmi/CellSession.h"
#include "screens/tooldata/ToolTableModel.h"

namespace mtc::screens {

ToolTableScreen::ToolTableScreen(const mtc::hmi::ScreenContext& context)
    : SetupTableScreen(context, "tool") {
    model_ = new ToolTableModel(context.session->setupData().tools(processNumber()), this);
    setModel(model_, false);
    model_->setCursor(0, ToolTableModel::Radius);
    updateHeading();
}

void ToolTableScreen::activated() {
    model_->refresh();
    updateHeading();
    showCursor();
}

void ToolTableScreen::updateHeading() {
    const std::string& file = context().session->setupEditor().files().tools;
    const auto& process = context().session->processConfig(context().process);
    setHeading(tr("Tool list of process %1 (%2): %3 edges\nFile: %4")
                   .arg(process.index)
                   .arg(QString::fromStdString(process.name))
                   .arg(model_->rowCount())
                   .arg(file.empty() ? tr("none, changes hold until the panel ends")
                                     : QString::fromStdString(file)));
}

mtc::hmi::SoftKeys ToolTableScreen::softKeys() {
    mtc::hmi::SoftKeys keys(8);
    keys[0] = {tr("Edit"), [this] { startEdit(); }};
    keys[1] = {tr("New tool"), [this] { askNewTool(); }};
    keys[2] = {tr("New edge"), [this] { askNewEdge(); }};
    keys[3] = {tr("Delete edge"), [this] { askRemoval(false); }};
    keys[4] = {tr("Delete tool"), [this] { askRemoval(true); }};
    keys[7] = {tr("Back"), [this] { emit navigateTo("menu"); }};
    return keys;
}

QString ToolTableScreen::edgeName() const {
    return QString("T%1 E%2").arg(model_->currentTool()).arg(model_->currentEdge());
}

void ToolTableScreen::ask(Input input, const QString& prompt, const QString& text) {
    input_ = input;
    openInput(prompt, text);
}

void ToolTableScreen::startEdit() {
    if (input_ != Input::None) return;
    if (model_->rowCount() == 0) {
        say(tr("The tool list is empty: F2 adds a tool"));
        return;
    }
    const int column = model_->cursorColumn();
    const std::string key = ToolTableModel::columnKey(column);
    if (key.empty()) {
        say(tr("The tool and edge numbers are not edited: F2 adds a tool, F3 an edge"));
        return;
    }
    ask(Input::Value,
        tr("New %1 of %2 (%3):")
            .arg(ToolTableModel::columnMeaning(column), edgeName(),
                 QString::fromStdString(mtc::core::toolValueRange(key))),
        model_->currentValueText());
}

void ToolTableScreen::askNewTool() {
    if (input_ != Input::None) return;
    ask(Input::NewTool, tr("Number of the new tool (1 .. %1):").arg(mtc::core::kMaxToolNumber), {});
}

void ToolTableScreen::askNewEdge() {
    if (input_ != Input::None) return;
    if (model_->rowCount() == 0) {
        say(tr("The tool list is empty: F2 adds a tool"));
        return;
    }
    ask(Input::NewEdge,
        tr("New cutting edge of T%1 (1 .. %2):")
            .arg(model_->currentTool())
            .arg(mtc::core::kMaxEdgeNumber),
        {});
}

void ToolTableScreen::askRemoval(bool wholeTool) {
    if (input_ != Input::None || model_->rowCount() == 0) return;
    const QString what = wholeTool ? tr("tool T%1 with all its edges").arg(model_->currentTool())
                                   : tr("edge %1").arg(edgeName());
    ask(wholeTool ? Input::RemoveTool : Input::RemoveEdge,
        tr("Delete %1? Enter deletes, Esc keeps it:").arg(what), {});
}

void ToolTableScreen::inputConfirmed(const QString& text) {
    const Input input = input_;
    input_ = Input::None;
    switch (input) {
        case Input::Value:
            confirmValue(text);
            break;
        case Input::NewTool:
            confirmNewTool(text);
            break;
        case Input::NewEdge:
            confirmNewEdge(text);
            break;
        case Input::RemoveEdge:
        case Input::RemoveTool:
            confirmRemoval(input == Input::RemoveTool);
            break;
        case Input::None:
            break;
    }
    updateHeading();
    showCursor();
}

void ToolTableScreen::inputCancelled() {
    const Input input = input_;
    input_ = Input::None;
    if (input == Input::Value)
        say(tr("Input cancelled: %1 %2 stays %3")
                .arg(edgeName(), ToolTableModel::columnMeaning(model_->cursorColumn()),
                     model_->currentValueText()));
    else
        say(tr("Cancelled: the tool list is unchanged"));
}

void ToolTableScreen::confirmValue(const QString& text) {
    const int column = model_->cursorColumn();
    const QString what = edgeName() + " " + ToolTableModel::columnMeaning(column);
    const QString old = model_->currentValueText();
    const mtc::core::SetupDataEdit edit = context().session->setupEditor().setToolValues(
        processNumber(), model_->currentTool(), model_->currentEdge(),
        {{ToolTableModel::columnKey(column), text.toStdString()}});
    model_->refresh();
    say(outcomeText(edit, what + " = " + model_->currentValueText(),
                    tr("%1 stays %2").arg(what, old)));
}

void ToolTableScreen::confirmNewTool(const QString& text) {
    const mtc::core::SetupDataEdit edit =
        context().session->setupEditor().addTool(processNumber(), text.toStdString());
    model_->refresh();
    if (edit.changed) {
        const QString digits = text.startsWith('T', Qt::CaseInsensitive) ? text.mid(1) : text;
        model_->showEdge(digits.toInt(), 1);
    }
    say(outcomeText(edit, tr("New tool %1: enter its values").arg(edgeName()),
                    tr("No tool was added")));
}

void ToolTableScreen::confirmNewEdge(const QString& text) {
    const int tool = model_->currentTool();
    const mtc::core::SetupDataEdit edit =
        context().session->setupEditor().addEdge(processNumber(), tool, text.toStdString());
    model_->refresh();
    if (edit.changed) {
        const QString digits = text.startsWith('E', Qt::CaseInsensitive) ? text.mid(1) : text;
        model_->showEdge(tool, digits.toInt());
    }
    say(outcomeText(edit, tr("New edge %1: enter its values").arg(edgeName()),
                    tr("No edge was added")));
}

void ToolTableScreen::confirmRemoval(bool wholeTool) {
    const int tool = model_->currentTool(), edge = model_->currentEdge();
    const QString what = wholeTool ? QString("T%1").arg(tool) : edgeName();
    mtc::core::SetupDataEditor& editor = context().session->setupEditor();
    const mtc::core::SetupDataEdit edit = wholeTool
                                              ? editor.removeTool(processNumber(), tool)
                                              : editor.removeEdge(processNumber(), tool, edge);
    model_->refresh();
    say(outcomeText(edit, tr("%1 deleted").arg(what), tr("%1 is kept").arg(what)));
}

}  // namespace mtc::screens
