#include "screens/tooldata/ZeroOffsetScreen.h"

#include "cnc_core/tooldata/DataFileText.h"
#include "cnc_core/tooldata/SetupDataEditor.h"
#include "cnc_core/tooldata/ZeroOffsetFile.h"
#include "hmi/CellSession.h"
#include "screens/tooldata/ZeroOffsetModel.h"

namespace mtc::screens {

ZeroOffsetScreen::ZeroOffsetScreen(const mtc::hmi::ScreenContext& context)
    : SetupTableScreen(context, "offset") {
    model_ = new ZeroOffsetModel(&context.session->processConfig(context.process),
                                 context.session->setupData().offsets(processNumber()), this);
    setModel(model_, true);
    updateHeading();
}

void ZeroOffsetScreen::activated() {
    model_->refresh();
    updateHeading();
    showCursor();
}

void ZeroOffsetScreen::updateHeading() {
    const std::string& file = context().session->setupEditor().files().offsets;
    const auto& process = context().session->processConfig(context().process);
    // Which axis can use which column (G20 may change an axis's definition).
    QString axes;
    for (const mtc::core::AxisConfig& axis : process.axes) {
        QStringList letters;
        for (const std::string& d : axis.definitions)
            if (d.size() == 1 &&
                mtc::core::definitionFromLetter(d[0]) != mtc::core::AxisDefinition::None)
                letters << QString::fromStdString(d);
        if (letters.isEmpty()) continue;  // a spindle
        axes += (axes.isEmpty() ? "" : "  ") + QString::fromStdString(axis.name) + ": " +
                letters.join('/');
    }
    setHeading(tr("Zero offsets of process %1 (%2). Columns are axis definitions (axis: "
                  "definitions %3)\nFile: %4")
                   .arg(process.index)
                   .arg(QString::fromStdString(process.name), axes,
                        file.empty() ? tr("none, changes hold until the panel ends")
                                     : QString::fromStdString(file)));
}

mtc::hmi::SoftKeys ZeroOffsetScreen::softKeys() {
    mtc::hmi::SoftKeys keys(8);
    keys[0] = {tr("Edit"), [this] { startEdit(); }};
    keys[7] = {tr("Back"), [this] { emit navigateTo("menu"); }};
    return keys;
}

QString ZeroOffsetScreen::cellName() const {
    return QString("G%1 %2").arg(model_->currentCode()).arg(QChar(model_->currentColumn()));
}

void ZeroOffsetScreen::startEdit() {
    if (editing_) return;
    if (model_->currentColumn() == '\0') {
        say(tr("Put the cursor on an axis column (cursor right) to change an offset"));
        return;
    }
    const std::string limit = mtc::core::formatDataNumber(mtc::core::kMaxZeroOffset);
    editing_ = true;
    openInput(tr("New zero offset %1 (-%2 .. %2 mm, degrees on a rotary axis):")
                  .arg(cellName(), QString::fromStdString(limit)),
              model_->currentValueText());
}

void ZeroOffsetScreen::inputConfirmed(const QString& text) {
    editing_ = false;
    const QString what = cellName();
    const QString old = model_->currentValueText();
    const mtc::core::SetupDataEdit edit = context().session->setupEditor().setOffsets(
        processNumber(), model_->currentCode(),
        {{std::string(1, model_->currentColumn()), text.toStdString()}});
    model_->refresh();
    say(outcomeText(edit, what + " = " + model_->currentValueText(),
                    tr("%1 stays %2").arg(what, old)));
    showCursor();
}

void ZeroOffsetScreen::inputCancelled() {
    editing_ = false;
    say(tr("Input cancelled: %1 stays %2").arg(cellName(), model_->currentValueText()));
}

}  // namespace mtc::screens
