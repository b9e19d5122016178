#include "screens/toolpath/ToolpathScreen.h"

#include <QBuffer>
#include <QDir>
#include <QGuiApplication>
#include <QKeyEvent>
#include <QLabel>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QStandardPaths>
#include <QVBoxLayout>

#include "cnc_core/program/AtomicWrite.h"
#include "hmi/CellSession.h"
#include "screens/restart/RestartController.h"
#include "screens/toolpath/PainterToolpathCanvas.h"
#include "screens/toolpath/ToolpathLink.h"
#include "screens/toolpath/ToolpathModel.h"
#include "screens/toolpath/VtkToolpathCanvas.h"

namespace mtc::screens {

bool openGlAvailable(QString& reason) {
    const QString platform = QGuiApplication::platformName();
    if (qEnvironmentVariableIsSet("MTC_TOOLPATH_2D")) {
        reason = ToolpathScreen::tr("MTC_TOOLPATH_2D is set");
        return false;
    }
    if (platform == "offscreen" || platform == "minimal") {
        reason = ToolpathScreen::tr("the Qt platform '%1' has no OpenGL").arg(platform);
        return false;
    }
    QOpenGLContext context;
    if (!context.create()) {
        reason = ToolpathScreen::tr("no OpenGL context can be created");
        return false;
    }
    QOffscreenSurface surface;
    surface.setFormat(context.format());
    surface.create();
    if (!surface.isValid() || !context.makeCurrent(&surface)) {
        reason = ToolpathScreen::tr("the OpenGL context cannot be made current");
        return false;
    }
    context.doneCurrent();
    return true;
}

ToolpathScreen::ToolpathScreen(const mtc::hmi::ScreenContext& context,
                               std::shared_ptr<RestartController> restart,
                               std::shared_ptr<ToolpathLink> link)
    : Screen(context), restart_(std::move(restart)) {
    model_ = new ToolpathModel(context.session, context.process, restart_, std::move(link), this);
    summary_ = new QLabel(this);
    summary_->setObjectName("toolpathSummary");
    summary_->setWordWrap(true);
    summary_->setStyleSheet("background: #dfe6ef; padding: 3px; font-weight: bold;");
    if (openGlAvailable(glReason_))
        canvas_ = new VtkToolpathCanvas(model_, this);
    else
        canvas_ = new PainterToolpathCanvas(model_, this);
    legend_ = new QLabel(this);
    legend_->setObjectName("toolpathLegend");
    legend_->setTextFormat(Qt::RichText);
    legend_->setStyleSheet(QString("background: %1; color: white; padding: 2px 4px;")
                               .arg(model_->palette().background.name()));
    message_ = new QLabel(this);
    message_->setObjectName("toolpathMessage");
    message_->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(summary_);
    layout->addWidget(canvas_, 1);
    layout->addWidget(legend_);
    layout->addWidget(message_);
    setFocusPolicy(Qt::StrongFocus);
    connect(model_, &ToolpathModel::marksChanged, this, &ToolpathScreen::renderText);
    connect(model_, &ToolpathModel::geometryChanged, this, &ToolpathScreen::renderText);
    connect(model_, &ToolpathModel::partChanged, this, &ToolpathScreen::renderText);
    connect(model_, &ToolpathModel::geometryChanged, this, [this] {
        if (!showingAll_) return;
        showingAll_ = false;  // a new picture is framed to its part
        emit softKeysChanged();
    });
    connect(context.session, &mtc::hmi::CellSession::processChanged, this, [this](int slot) {
        if (slot == this->context().process && isVisible()) model_->refresh();
    });
    if (!glReason_.isEmpty())
        message_->setText(tr("2D view: %1 (the 3D view needs OpenGL).").arg(glReason_));
}

ToolpathScreen::~ToolpathScreen() = default;

void ToolpathScreen::activated() {
    model_->refresh();
    renderText();
}

QString ToolpathScreen::legendText() const {
    const ToolpathPalette& p = model_->palette();
    auto swatch = [](const QColor& colour, const QString& text) {
        return QString("<span style='color:%1'>&#9632;</span> %2").arg(colour.name(), text);
    };
    QString text = tr("Tool centre path:") + " " + swatch(p.rapid, "G0") + " &nbsp;" +
                   swatch(p.feed, "G1") + " &nbsp;" + swatch(p.arc, "G2/G3");
    const auto g = model_->geometry();
    if (g && g->contour.segmentCount() + g->developedContour.segmentCount() > 0)
        text += " &nbsp;&nbsp; " + swatch(p.contour, tr("programmed contour (G41/G42, edge, G48)"));
    if (!model_->backplot(false).empty() || !model_->backplot(true).empty())
        text += " &nbsp;&nbsp; " + swatch(p.backplot, tr("travelled since Start"));
    const QString part = model_->part().note;
    if (model_->partShown())  // both views draw it (TP-023, TP-030)
        text += " &nbsp;&nbsp; " + swatch(p.part, part + " " + tr("(M hides)"));
    else if (g && !part.isEmpty())
        text += " &nbsp;&nbsp; " + part;
    return text;
}

void ToolpathScreen::renderText() {
    summary_->setText(model_->summary());
    legend_->setText(legendText());
    QString line = tr("Linked to the %1").arg(model_->partnerName());
    if (!model_->highlightText().isEmpty())
        line += " · " + (model_->highlightsRunningBlock()
                             ? tr("running: %1").arg(model_->highlightText())
                             : tr("highlighted: %1").arg(model_->highlightText()));
    if (!model_->problem().isEmpty()) line += (line.isEmpty() ? "" : " · ") + model_->problem();
    if (!glReason_.isEmpty())
        line += (line.isEmpty() ? "" : " · ") + tr("2D view: %1").arg(glReason_);
    message_->setText(line);
}

void ToolpathScreen::preset(ToolpathPreset p) {
    canvas_->showPreset(p);  // frames the part
    if (showingAll_) {
        showingAll_ = false;
        emit softKeysChanged();
    }
    message_->setText(tr("View %1").arg(p == ToolpathPreset::Isometric ? tr("isometric")
                                                                       : QString(presetName(p))));
}

void ToolpathScreen::fitNext() {
    if (showingAll_) return fitPart();
    canvas_->fitAll();
    showingAll_ = true;
    message_->setText(tr("Every move framed, rapids included (F5: the part again)."));
    emit softKeysChanged();
}

void ToolpathScreen::fitPart() {
    canvas_->fit();
    message_->setText(tr("The part framed: cutting moves and stock (F5: every move)."));
    if (showingAll_) {
        showingAll_ = false;
        emit softKeysChanged();
    }
}

QString ToolpathScreen::defaultExportPath() const {
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation);
    QDir().mkpath(dir);
    return dir + QString("/toolpath-P%1.png").arg(model_->programNumber());
}

bool ToolpathScreen::exportPng(const QString& path) {
    const QImage image = canvas_->picture();
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    std::string error;
    if (image.isNull() || !image.save(&buffer, "PNG")) {
        message_->setText(tr("The view could not be turned into a PNG picture."));
        return false;
    }
    if (!mtc::core::writeFileAtomically(path.toStdString(),
                                        std::string_view(bytes.constData(), bytes.size()), error)) {
        message_->setText(tr("PNG not written: %1").arg(QString::fromStdString(error)));
        return false;
    }
    message_->setText(tr("View written to %1").arg(path));
    return true;
}

void ToolpathScreen::keyPressEvent(QKeyEvent* event) {
    const bool shift = event->modifiers() & Qt::ShiftModifier;
    const double step = 15.0, panStep = 0.1;
    switch (event->key()) {
        case Qt::Key_1:
            return preset(ToolpathPreset::G17);
        case Qt::Key_2:
            return preset(ToolpathPreset::G18);
        case Qt::Key_3:
            return preset(ToolpathPreset::G19);
        case Qt::Key_4:
            return preset(ToolpathPreset::Isometric);
        case Qt::Key_0:
        case Qt::Key_Home:
            return fitPart();
        case Qt::Key_Plus:
            return canvas_->zoom(1.25);
        case Qt::Key_Minus:
            return canvas_->zoom(0.8);
        case Qt::Key_Left:
            return shift ? canvas_->pan(-panStep, 0) : canvas_->rotate(-step, 0);
        case Qt::Key_Right:
            return shift ? canvas_->pan(panStep, 0) : canvas_->rotate(step, 0);
        case Qt::Key_Up:
            return shift ? canvas_->pan(0, panStep) : canvas_->rotate(0, step);
        case Qt::Key_Down:
            return shift ? canvas_->pan(0, -panStep) : canvas_->rotate(0, -step);
        case Qt::Key_PageDown:
            return model_->step(+1);
        case Qt::Key_PageUp:
            return model_->step(-1);
        case Qt::Key_P:
            exportPng(defaultExportPath());
            return;
        case Qt::Key_M:  // the finished part (TP-023)
            model_->togglePart();
            return;
        default:
            Screen::keyPressEvent(event);
    }
}

mtc::hmi::SoftKeys ToolpathScreen::softKeys() {
    mtc::hmi::SoftKeys keys(8);
    keys[0] = {tr("G17\nview"), [this] { preset(ToolpathPreset::G17); }};
    keys[1] = {tr("G18\nview"), [this] { preset(ToolpathPreset::G18); }};
    keys[2] = {tr("G19\nview"), [this] { preset(ToolpathPreset::G19); }};
    keys[3] = {tr("Iso-\nmetric"), [this] { preset(ToolpathPreset::Isometric); }};
    keys[4] = {showingAll_ ? tr("Fit\npart") : tr("Fit\nall"), [this] { fitNext(); }};
    keys[5] = {tr("Export\nPNG"), [this] { exportPng(defaultExportPath()); }};
    keys[6] = {tr("Restart"), [this] { emit navigateTo("restart"); }};
    keys[7] = {tr("Back"), [this] { emit navigateTo("menu"); }};
    return keys;
}

}  // namespace mtc::screens
