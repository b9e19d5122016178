// Toolpath screen without OpenGL (offscreen platform, no X server): the
// screen detects it before creating anything of VTK and shows the 2D view;
// keys, highlight, picking and the link with the restart screen work there
// too, and the view exports a PNG. The 3D view is tested in tests/gl.
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QTemporaryDir>
#include <algorithm>
#include <cmath>

#include "PanelFixture.h"
#include "resources/EmbeddedResources.h"
#include "screens/restart/RestartController.h"
#include "screens/toolpath/PainterToolpathCanvas.h"
#include "screens/toolpath/ToolpathCanvas.h"
#include "screens/toolpath/ToolpathModel.h"
#include "screens/toolpath/ToolpathScreen.h"
#include "screens/toolpath/ToolpathTicks.h"

using mtc::screens::ToolpathScreen;

namespace {

ToolpathScreen* toolpath(PanelFixture& panel, int slot = 0) {
    return static_cast<ToolpathScreen*>(panel.window->screen(slot, "toolpath"));
}

/// Pixels of exactly `colour` in `image`.
int count(const QImage& image, const QColor& colour) {
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    int n = 0;
    for (int y = 0; y < rgb.height(); ++y)
        for (int x = 0; x < rgb.width(); ++x)
            if (QColor(rgb.pixel(x, y)).rgb() == colour.rgb()) ++n;
    return n;
}

/// Length (mm) of the backplot the view draws in the scene.
double travelled(const mtc::screens::ToolpathModel& model) {
    const mtc::screens::ToolpathBackplot b = model.backplot(false);
    if (b.empty()) return 0.0;
    const auto distance = [](const std::array<double, 3>& p, const std::array<double, 3>& q) {
        return std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
    };
    double length = 0.0;
    for (std::uint32_t s = 0; s < b.segments; ++s)
        length += distance(b.layer->vertex(b.layer->segmentStart[s]),
                           b.layer->vertex(b.layer->segmentStart[s] + 1));
    if (b.partial) length += distance(b.partialFrom, b.partialTo);
    return length;
}

/// The tick labels of scene axis `axis` the 2D view drew at its last paint.
QList<const mtc::screens::ToolpathTick*> ticksOf(const mtc::screens::PainterToolpathCanvas& canvas,
                                                 int axis) {
    QList<const mtc::screens::ToolpathTick*> out;
    for (const auto& tick : canvas.rulers(false).ticks)
        if (tick.axis == axis) out << &tick;
    return out;
}

/// Rows of `colour` in column `x` of `image`.
int thickness(const QImage& image, int x, const QColor& colour) {
    int rows = 0;
    for (int y = 0; y < image.height(); ++y)
        if (QColor(image.pixel(x, y)).rgb() == colour.rgb()) ++rows;
    return rows;
}

}  // namespace

class ToolpathScreenTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { useTestSettings(); }

    void offscreenShowsTheTwoDimensionalViewWithoutAborting() {
        PanelFixture panel;
        panel.session->selectProgram(0, 1);
        QVERIFY(panel.window->showScreen("toolpath"));
        ToolpathScreen* screen = toolpath(panel);
        QVERIFY(screen->findChild<QWidget*>("toolpathPainter"));
        QVERIFY(!screen->findChild<QWidget*>("toolpathVtkWidget"));
        QVERIFY(!screen->canvas()->threeD());
        QVERIFY(screen->findChild<QLabel*>("toolpathMessage")->text().contains("offscreen"));
        QString reason;
        QVERIFY(!mtc::screens::openGlAvailable(reason));
        QVERIFY(reason.contains("offscreen"));
        QTRY_VERIFY(screen->model()->geometry() != nullptr);
        QVERIFY(screen->model()->geometry()->scene.segmentCount() > 10);
        QVERIFY(screen->findChild<QLabel*>("toolpathSummary")->text().startsWith("P1"));
        const QImage picture = screen->canvas()->picture();
        const auto& palette = screen->model()->palette();
        QVERIFY(count(picture, palette.feed) > 50);
        QVERIFY(count(picture, palette.rapid) > 10);
    }

    void keysMoveTheHighlightAndTheViewAndPickingSelectsTheBlock() {
        PanelFixture panel;
        panel.session->selectProgram(0, 1);
        panel.window->showScreen("toolpath");
        ToolpathScreen* screen = toolpath(panel);
        auto* model = screen->model();
        QVERIFY(model->highlighted().empty());
        panel.press(Qt::Key_PageDown);
        panel.press(Qt::Key_PageDown);
        const auto& moves = model->highlighted();
        QVERIFY(std::find(moves.begin(), moves.end(), 1u) != moves.end());
        QVERIFY(model->highlightText().startsWith("P1 N"));
        // The approach lies outside the part the view frames: F5 frames every move.
        panel.press(Qt::Key_F5);
        QVERIFY(count(screen->canvas()->picture(), model->palette().highlight) > 0);
        panel.press(Qt::Key_1);
        QVERIFY(screen->findChild<QLabel*>("toolpathMessage")->text().contains("G17"));
        const QImage top = screen->canvas()->picture();
        panel.press(Qt::Key_4);
        panel.press(Qt::Key_Left);
        panel.press(Qt::Key_Plus);
        panel.press(Qt::Key_Up, Qt::ShiftModifier);
        QVERIFY(screen->canvas()->picture() != top);
        // Picking: a click on the middle of a move's first segment selects it.
        panel.press(Qt::Key_1);
        const auto& g = *model->geometry();
        long picked = -1;
        for (long m = static_cast<long>(g.moves.size()) - 1; m >= 0 && picked < 0; --m) {
            const auto at = screen->canvas()->positionOfMove(m);
            if (!at) continue;
            QTest::mouseClick(screen->canvas(), Qt::LeftButton, {}, *at);
            if (!model->highlighted().empty()) picked = m;
        }
        QVERIFY(picked >= 0);
        const auto& chosen = g.moves[static_cast<std::size_t>(model->highlighted().front())];
        QCOMPARE(chosen.block, g.moves[static_cast<std::size_t>(picked)].block);
    }

    /// TP-023: the finished part is simulated with the path (its volume in
    /// the legend, also in the 2D view); a stock too large for 0.2 mm in
    /// the view's cell budget is simulated coarser, and the legend says so.
    void theFinishedPartIsSimulatedAtAResolutionTheViewCanHold() {
        {
            PanelFixture panel;
            panel.session->selectProgram(0, 1);
            panel.window->showScreen("toolpath");
            const auto* model = toolpath(panel)->model();
            QVERIFY2(model->part().note.contains("removed at 0.2 mm"),
                     qPrintable(model->part().note));
            QVERIFY(!model->part().triangles.empty());
            QVERIFY(child<QLabel>(panel, "toolpath", "toolpathLegend")
                        ->text()
                        .contains(model->part().note));
        }
        // The mill's stock 600 x 600 mm: 9,000,000 cells at 0.2 mm, 90,000 at 2.
        QTemporaryDir dir;
        std::string cell(mtc::resources::find(mtc::resources::kDemoCellName));
        const std::string demoStock = "stock = block -150 -50 -80 -20 -132 -120";
        const std::size_t at = cell.find(demoStock);
        QVERIFY(at != std::string::npos);
        cell.replace(at, demoStock.size(), "stock = block -450 150 -480 120 -132 -120");
        QFile file(dir.filePath("big-stock.cfg"));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(cell.data(), static_cast<qint64>(cell.size()));
        file.close();
        mtc::hmi::PanelOptions options;
        options.machineFile = file.fileName();
        PanelFixture panel(options);
        panel.session->selectProgram(0, 1);
        panel.window->showScreen("toolpath");
        const auto* model = toolpath(panel)->model();
        QVERIFY2(model->part().note.contains("removed at 2 mm"), qPrintable(model->part().note));
        QVERIFY2(model->part().triangles.size() < 9 * 200'000u * 2,
                 qPrintable(QString::number(model->part().triangles.size())));
    }

    /// TP-014: the view frames the cutting moves and the stock, not the
    /// approach from the tool-change position; F5 toggles to every move.
    void theViewFramesThePartAndF5FramesEveryMove() {
        PanelFixture panel;
        panel.session->selectProgram(0, 1);
        panel.window->showScreen("toolpath");
        ToolpathScreen* screen = toolpath(panel);
        const auto* model = screen->model();
        const mtc::core::ToolpathBounds part = model->frame(false, false);
        const mtc::core::ToolpathBounds all = model->frame(false, true);
        const auto& stock = model->stock();
        QVERIFY(!part.empty);
        for (int i = 0; i < 3; ++i) {  // the stock is inside the part's frame
            QVERIFY(part.min[i] <= stock.min[i] + 1e-9);
            QVERIFY(part.max[i] >= stock.max[i] - 1e-9);
        }
        // The approach from Z far above the plate is not.
        QVERIFY2(all.max[2] > part.max[2] + 50.0,
                 qPrintable(QString("%1 %2").arg(all.max[2]).arg(part.max[2])));
        const auto label = [&] { return screen->softKeys().value(4).label; };
        QCOMPARE(label(), QString("Fit\nall"));
        const QImage framedPart = screen->canvas()->picture();
        panel.press(Qt::Key_F5);
        QCOMPARE(label(), QString("Fit\npart"));
        QVERIFY(screen->canvas()->picture() != framedPart);
        panel.press(Qt::Key_F5);
        QCOMPARE(label(), QString("Fit\nall"));
        panel.press(Qt::Key_F5);
        panel.press(Qt::Key_1);  // a preset frames the part again
        QCOMPARE(label(), QString("Fit\nall"));
    }

    /// TP-015: the tool is drawn where the axes are, and moves with them
    /// while the program runs (Start, Shift+F5).
    void theToolFollowsTheActualPosition() {
        PanelFixture panel;
        panel.session->selectProgram(0, 1);
        panel.window->showScreen("toolpath");
        ToolpathScreen* screen = toolpath(panel);
        const auto* model = screen->model();
        const auto sceneOfMachine = [&] {
            const auto& machine = panel.session->station(0).machine();
            return std::array<double, 3>{machine.position(0), machine.position(1),
                                         machine.position(2)};
        };
        mtc::screens::ToolpathMarks before = model->marks();
        QVERIFY(before.hasTool);
        QVERIFY(!before.turning);
        for (int i = 0; i < 3; ++i)
            QCOMPARE(before.tool[i], sceneOfMachine()[i]);
        panel.press(Qt::Key_F5);  // every move: the tool's start is far from the part
        QVERIFY(count(screen->canvas()->picture(), model->palette().tool) > 20);
        panel.session->setSpeed(mtc::hmi::CellSession::kMaxSpeed);
        panel.press(Qt::Key_F5, Qt::ShiftModifier);
        QTRY_VERIFY_WITH_TIMEOUT(!panel.session->control(0).programActive(), 20000);
        QCOMPARE(QString::fromStdString(panel.session->control(0).alarm()), QString());
        const mtc::screens::ToolpathMarks after = model->marks();
        for (int i = 0; i < 3; ++i)
            QCOMPARE(after.tool[i], sceneOfMachine()[i]);
        QVERIFY(after.tool != before.tool);
        QVERIFY(after.toolRadius > 0.0);  // the program's tool is in the tool list
        // Parked at the tool-change position, outside the part: every move framed.
        if (screen->softKeys().value(4).label == QString("Fit\nall")) panel.press(Qt::Key_F5);
        QVERIFY(count(screen->canvas()->picture(), model->palette().tool) > 20);
    }

    /// TP-016, TP-017: while the program runs (Start), the backplot grows
    /// with the station's time and ends at the tool, the running block is
    /// highlighted; Stop (feed hold) stops it growing, Control reset ends it
    /// where the axes stopped, a new Start begins a new one.
    void theBackplotGrowsWhileTheProgramRunsAndTheRunningBlockIsHighlighted() {
        PanelFixture panel;
        panel.session->selectProgram(0, 1);
        panel.window->showScreen("toolpath");
        panel.session->setTimerEnabled(false);  // the test gives the station its time
        ToolpathScreen* screen = toolpath(panel);
        const auto* model = screen->model();
        const auto& palette = model->palette();
        QVERIFY(model->backplot(false).empty());
        QCOMPARE(count(screen->canvas()->picture(), palette.backplot), 0);
        QVERIFY(!screen->findChild<QLabel*>("toolpathLegend")->text().contains("since Start"));
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start
        QVERIFY(panel.session->control(0).programActive());
        const auto& station = panel.session->station(0);
        // Until the first feed move (the contour: moves without waits follow).
        const auto feeding = [&] {
            const auto* move = station.machine().engine().currentMove();
            return move && !move->rapid;
        };
        for (int tick = 0; tick < 2000 && !feeding(); ++tick)
            panel.session->advance(0.05);
        QVERIFY(feeding());
        double before = travelled(*model);
        QVERIFY2(before > 0.0, "the approach is in the backplot");
        for (int tick = 0; tick < 5; ++tick) {
            panel.session->advance(0.1);
            const double now = travelled(*model);
            QVERIFY2(now > before, qPrintable(QString("%1 after %2").arg(now).arg(before)));
            before = now;
            // It ends at the tool (the demo mill has no tool offsets in the plane).
            const auto b = model->backplot(false);
            const auto end = b.partial ? b.partialTo
                                       : b.layer->vertex(b.layer->segmentStart[b.segments - 1] + 1);
            QVERIFY(std::abs(end[0] - station.machine().position(0)) < 1e-3);
            QVERIFY(std::abs(end[1] - station.machine().position(1)) < 1e-3);
            // The running block is highlighted: the block the machine executes.
            QVERIFY(model->highlightsRunningBlock());
            const auto* executing = station.executingBlockState();
            QVERIFY(executing);
            const auto& g = *model->geometry();
            QVERIFY(!model->highlighted().empty());
            QCOMPARE(g.moves[model->highlighted().front()].block, executing->index);
            QVERIFY(screen->findChild<QLabel*>("toolpathMessage")->text().contains("running: P1"));
        }
        QVERIFY(count(screen->canvas()->picture(), palette.backplot) > 10);
        QVERIFY(screen->findChild<QLabel*>("toolpathLegend")->text().contains("since Start"));
        panel.press(Qt::Key_F6, Qt::ShiftModifier);  // Stop: feed hold
        panel.session->advance(2.0);                 // the axes brake and stand
        const double held = travelled(*model);
        panel.session->advance(3.0);
        QCOMPARE(travelled(*model), held);
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start goes on
        panel.session->advance(0.5);
        QVERIFY(travelled(*model) > held);
        panel.press(Qt::Key_F7, Qt::ShiftModifier);  // Control reset
        const double stopped = travelled(*model);
        panel.session->advance(1.0);
        QCOMPARE(travelled(*model), stopped);
        QVERIFY(!model->highlightsRunningBlock());
        QVERIFY(count(screen->canvas()->picture(), palette.backplot) > 10);
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // a new Start: a new backplot
        QVERIFY(travelled(*model) < stopped);
        for (int tick = 0; tick < 400 && travelled(*model) <= 0.0; ++tick)
            panel.session->advance(0.1);
        QVERIFY(travelled(*model) > 0.0);
    }

    void restartCursorAndToolpathFollowEachOther() {
        PanelFixture panel;
        panel.session->selectProgram(0, 1);
        panel.press(Qt::Key_F1, Qt::ShiftModifier);  // M key: NC program restart
        QCOMPARE(panel.window->currentScreenName(), QString("restart"));
        for (int i = 0; i < 6; ++i)
            panel.press(Qt::Key_Down);  // N0006 Z2
        panel.window->showScreen("toolpath");
        ToolpathScreen* screen = toolpath(panel);
        auto* model = screen->model();
        const std::uint32_t cursor = 6;
        QVERIFY(!model->highlighted().empty());
        QCOMPARE(model->geometry()->moves[model->highlighted().front()].block, cursor);
        QVERIFY(model->marks().hasTarget);
        QVERIFY(model->marks().hasStart);
        // PgDn in the toolpath moves the restart cursor to the next move's block.
        panel.press(Qt::Key_PageDown);
        const auto next = model->geometry()->moves[model->highlighted().front()].block;
        QVERIFY(next > cursor);
        // The restart cursor (the target before Enter) moved there too.
        const auto& g = *model->geometry();
        const auto [first, last] = g.sceneRange(model->highlighted().front());
        QVERIFY(first < last);
        const auto expected = g.scene.vertex(g.scene.segmentStart[first]);
        const auto marks = model->marks();
        QVERIFY(marks.hasTarget);
        for (int i = 0; i < 3; ++i)
            QCOMPARE(marks.target[static_cast<std::size_t>(i)],
                     expected[static_cast<std::size_t>(i)]);
    }

    void exportWritesAPngFile() {
        PanelFixture panel;
        panel.session->selectProgram(0, 1);
        panel.window->showScreen("toolpath");
        QTemporaryDir dir;
        const QString path = dir.filePath("view.png");
        QVERIFY(toolpath(panel)->exportPng(path));
        QImage image(path);
        QVERIFY(!image.isNull());
        QVERIFY(image.width() > 100);
        QVERIFY(!toolpath(panel)->exportPng(dir.filePath("missing/dir/view.png")));
        QVERIFY(
            toolpath(panel)->findChild<QLabel*>("toolpathMessage")->text().contains("not written"));
    }

    /// TP-019: the view names the zero offset of the block it shows, in
    /// the 2D view's caption, and follows the program from G54 to G55:
    /// picked with PgDn and while the program runs.
    void theCaptionNamesTheZeroOffsetInUseAndFollowsTheProgram() {
        PanelFixture panel;
        // Demo mill: G54 = X-150 Y-80 Z-120, G55 = X50 Y-80 Z-120.
        panel.session->addProgram(0, 50, "two-vices.nc",
                                  "N0001 G54 G0 X5 Y5 Z5\nN0002 G1 Z-2 F2000\nN0003 X40\n"
                                  "N0004 G0 Z5\nN0005 G55 G0 X5 Y5\nN0006 G1 Z-2\n"
                                  "N0007 X40\nN0008 G0 Z5\nN0009 M30\n");
        panel.session->selectProgram(0, 50);
        panel.window->showScreen("toolpath");
        panel.session->setTimerEnabled(false);  // the test gives the station its time
        ToolpathScreen* screen = toolpath(panel);
        const auto* model = screen->model();
        auto* canvas = qobject_cast<mtc::screens::PainterToolpathCanvas*>(screen->canvas());
        QVERIFY(canvas);
        QTRY_VERIFY(model->geometry() != nullptr);
        const QString g54 =
            "Workpiece coordinates G54,\nzero point at machine X-150.000 "
            "Y-80.000 Z-120.000";
        const QString g55 =
            "Workpiece coordinates G55,\nzero point at machine X50.000 "
            "Y-80.000 Z-120.000";
        // Nothing highlighted: the offset in force at the end of the path.
        QVERIFY2(canvas->caption(false).endsWith(g55), qPrintable(canvas->caption(false)));
        QVERIFY(!canvas->caption(true).contains("G55"));
        panel.press(Qt::Key_PageDown);  // N0001 G54 G0 ...
        QVERIFY2(canvas->caption(false).endsWith(g54), qPrintable(canvas->caption(false)));
        QCOMPARE(model->axisTitle(0), QString("X (mm, G54)"));
        const QImage inG54 = canvas->picture();
        for (int i = 0; i < 4; ++i)
            panel.press(Qt::Key_PageDown);  // N0005 G55 G0 X5 Y5
        QVERIFY(model->highlightText().contains("N0005"));
        QVERIFY2(canvas->caption(false).endsWith(g55), qPrintable(canvas->caption(false)));
        QCOMPARE(model->axisTitle(2), QString("Z (mm, G55)"));
        QVERIFY(canvas->picture() != inG54);
        // While the program runs: the offset of the move the machine executes.
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start
        QVERIFY(panel.session->control(0).programActive());
        QStringList seen;
        for (int tick = 0; tick < 3000 && panel.session->control(0).programActive(); ++tick) {
            panel.session->advance(0.02);
            if (!model->highlightsRunningBlock()) continue;
            const QString code = canvas->caption(false).contains(g54)   ? "G54"
                                 : canvas->caption(false).contains(g55) ? "G55"
                                                                        : "?";
            if (seen.isEmpty() || seen.back() != code) seen << code;
        }
        QCOMPARE(seen, QStringList({"G54", "G55"}));
    }

    /// TP-025: the 2D view labels the two axes of a plane view in workpiece
    /// coordinates (G54), each value once, labels apart, and a finer step
    /// after zooming in; the axis seen end-on gets none.
    void theTwoDViewTicksReadWorkpieceCoordinatesAndFollowTheZoom() {
        PanelFixture panel;
        // Demo mill: G54 = X-150 Y-80 Z-120, stock X0..100 Y0..60 Z-12..0 at G54.
        panel.session->addProgram(0, 50, "plate.nc",
                                  "N0001 G54 G0 X0 Y0 Z5\nN0002 G1 Z-2 F500\nN0003 X100\n"
                                  "N0004 Y60\nN0005 X0\nN0006 Y0\nN0007 G0 Z5\nN0008 M30\n");
        panel.session->selectProgram(0, 50);
        panel.window->showScreen("toolpath");
        ToolpathScreen* screen = toolpath(panel);
        auto* canvas = qobject_cast<mtc::screens::PainterToolpathCanvas*>(screen->canvas());
        QVERIFY(canvas);
        QTRY_VERIFY(screen->model()->geometry() != nullptr);
        panel.press(Qt::Key_1);  // G17 view
        canvas->picture();
        const auto x = ticksOf(*canvas, 0), y = ticksOf(*canvas, 1);
        QVERIFY(ticksOf(*canvas, 2).isEmpty());  // Z is seen end-on
        QVERIFY2(x.size() >= 3 && y.size() >= 2,
                 qPrintable(QString("%1 X, %2 Y ticks").arg(x.size()).arg(y.size())));
        QStringList xTexts, yTexts;
        for (const auto* t : x)
            xTexts << t->text;
        for (const auto* t : y)
            yTexts << t->text;
        QVERIFY2(xTexts.contains("0") && xTexts.contains("100"), qPrintable(xTexts.join(' ')));
        QVERIFY2(yTexts.contains("0") || yTexts.contains("60"), qPrintable(yTexts.join(' ')));
        QCOMPARE(xTexts.removeDuplicates(), 0);
        QCOMPARE(yTexts.removeDuplicates(), 0);
        // X grows to the right along one row, Y upwards along one column.
        for (int i = 1; i < x.size(); ++i) {
            QVERIFY(x[i]->value > x[i - 1]->value && x[i]->box.left() > x[i - 1]->box.right());
            QCOMPARE(x[i]->box.top(), x[0]->box.top());
        }
        for (int i = 1; i < y.size(); ++i)
            QVERIFY(y[i]->value > y[i - 1]->value && y[i]->box.bottom() < y[i - 1]->box.top());
        // The tick of X0 is where the path's X0 (machine X-150) is drawn.
        const auto zero = std::find_if(x.begin(), x.end(), [](auto* t) { return t->value == 0; });
        const auto start = canvas->positionOfMove(2);  // N0003 X0 -> X100 at Y0
        QVERIFY(start);
        const double stepX = x[1]->value - x[0]->value;
        const double pixelsPerStep = x[1]->at.x() - x[0]->at.x();
        QVERIFY(std::abs((*zero)->at.x() + 50.0 / stepX * pixelsPerStep - start->x()) <= 1.0);
        const auto& rulers = canvas->rulers(false);
        QCOMPARE(rulers.titles.size(), std::size_t(2));
        QCOMPARE(rulers.titles[0].text, QString("X (mm, G54)"));
        for (std::size_t i = 0; i < rulers.ticks.size(); ++i)
            for (std::size_t j = i + 1; j < rulers.ticks.size(); ++j)
                QVERIFY(!rulers.ticks[i].box.intersects(rulers.ticks[j].box));
        // Zoomed in four times: a finer step, still every value once.
        for (int i = 0; i < 4; ++i)
            panel.press(Qt::Key_Plus);
        canvas->picture();
        const auto closer = ticksOf(*canvas, 0);
        QVERIFY(closer.size() >= 3);
        QVERIFY2(closer[1]->value - closer[0]->value < stepX,
                 qPrintable(
                     QString("step %1 -> %2").arg(stepX).arg(closer[1]->value - closer[0]->value)));
        QStringList closerTexts;
        for (const auto* t : closer)
            closerTexts << t->text;
        QCOMPARE(closerTexts.removeDuplicates(), 0);
    }

    /// TP-020 in the 2D view: the demo lathe programs radii and its X title
    /// says so; a G16 block's X ticks read diameters (the D80 bar: 80).
    void theTwoDLatheViewReadsRadiusOrDiameterAsProgrammed() {
        PanelFixture panel;
        panel.window->showStation(1);
        panel.session->addProgram(1, 50, "diameter.nc",
                                  "N0001 G54 G0 X45 Z5\nN0002 G1 Z-30 F200\nN0003 G16\n"
                                  "N0004 G1 X70 Z-40\nN0005 G0 X100\nN0006 M30\n");
        panel.session->selectProgram(1, 50);
        panel.window->showScreen("toolpath");
        ToolpathScreen* screen = toolpath(panel, 1);
        auto* canvas = qobject_cast<mtc::screens::PainterToolpathCanvas*>(screen->canvas());
        QVERIFY(canvas);
        QTRY_VERIFY(screen->model()->geometry() != nullptr);
        panel.press(Qt::Key_2);         // G18 view: Z across, X up
        panel.press(Qt::Key_PageDown);  // N0001, radius programming
        QVERIFY(screen->model()->highlightText().contains("N0001"));
        const auto along = canvas->positionOfMove(1);  // N0002 G1 Z-30 at X45 (radius)
        QVERIFY(along);
        // Where the X ruler puts `value`, from its first two ticks.
        const auto rowOf = [&](double value) {
            const auto x = ticksOf(*canvas, 0);
            const double slope = (x[1]->at.y() - x[0]->at.y()) / (x[1]->value - x[0]->value);
            return x[0]->at.y() + (value - x[0]->value) * slope;
        };
        const auto titles = [&] {
            QStringList texts;
            for (const auto& t : canvas->rulers(false).titles)
                texts << t.text;
            return texts;
        };
        canvas->picture();
        QVERIFY(ticksOf(*canvas, 0).size() >= 2);
        QVERIFY2(std::abs(rowOf(45) - along->y()) <= 1.0, qPrintable(QString::number(rowOf(45))));
        QVERIFY2(titles().contains("X (mm, radius, G54)"), qPrintable(titles().join('|')));
        for (int i = 0; i < 5 && !screen->model()->highlightText().contains("N0004"); ++i)
            panel.press(Qt::Key_PageDown);  // on to N0004 under G16
        QVERIFY(screen->model()->highlightText().contains("N0004"));
        canvas->picture();
        QVERIFY(ticksOf(*canvas, 0).size() >= 2);
        // The same line now reads its diameter 90.
        QVERIFY2(std::abs(rowOf(90) - along->y()) <= 1.0, qPrintable(QString::number(rowOf(90))));
        QVERIFY2(titles().contains(QString::fromUtf8("X (mm, \u00d8, G54)")),
                 qPrintable(titles().join('|')));
    }

    /// TP-026: the path is drawn one pixel wide at 96 dpi and wider on a
    /// denser screen (ctest runs this again with QT_FONT_DPI=144 and with
    /// QT_SCALE_FACTOR=1.5).
    void theLinesGrowWithTheScreensDpi() {
        PanelFixture panel;
        panel.session->addProgram(0, 50, "line.nc",
                                  "N0001 G54 G0 X0 Y30 Z5\nN0002 G1 Z-2 F500\nN0003 X100\n"
                                  "N0004 M30\n");
        panel.session->selectProgram(0, 50);
        panel.window->showScreen("toolpath");
        ToolpathScreen* screen = toolpath(panel);
        auto* canvas = qobject_cast<mtc::screens::PainterToolpathCanvas*>(screen->canvas());
        QVERIFY(canvas);
        QTRY_VERIFY(screen->model()->geometry() != nullptr);
        panel.press(Qt::Key_1);  // G17: the X move is a horizontal line
        double ratio = 1.0;
        int expected = 1;
        lineWidthAtScale(*canvas, ratio, expected);
        if (QTest::currentTestFailed()) return;
        const QImage picture = canvas->picture().convertToFormat(QImage::Format_RGB32);
        const auto middle = canvas->positionOfMove(2);
        QVERIFY(middle);
        const int column = static_cast<int>(std::lround(middle->x() * ratio));
        QCOMPARE(thickness(picture, column, screen->model()->palette().feed), expected);
    }

    void latheGrooveShowsDevelopedPlaneAndCylinder() {
        PanelFixture panel;
        panel.window->showStation(1);
        panel.session->selectProgram(1, 1);
        panel.window->showScreen("toolpath");
        ToolpathScreen* screen = toolpath(panel, 1);
        const auto g = screen->model()->geometry();
        QVERIFY(g);
        QVERIFY(g->developed.segmentCount() > 0);
        QVERIFY(g->cylinderRadius > 0);
        QVERIFY(screen->model()->summary().contains("developed plane"));
        QVERIFY(screen->model()->stock().shape == mtc::core::Stock::Shape::Cylinder);
    }

    /// TP-031: the framed part keeps clear of the axis triad in the top
    /// right corner, in the developed plane and the scene of both machines
    /// and every preset, and still fills most of its free area.
    void theFramedPartKeepsClearOfTheTriad() {
        PanelFixture panel;
        for (int station : {0, 1}) {
            panel.window->showStation(station);
            panel.session->selectProgram(station, 1);
            panel.window->showScreen("toolpath");
            ToolpathScreen* screen = toolpath(panel, station);
            auto* canvas = qobject_cast<mtc::screens::PainterToolpathCanvas*>(screen->canvas());
            QVERIFY(canvas);
            QTRY_VERIFY(screen->model()->geometry() != nullptr);
            const bool split = screen->model()->geometry()->developed.segmentCount() > 0;
            for (Qt::Key preset : {Qt::Key_1, Qt::Key_2, Qt::Key_3, Qt::Key_4}) {
                panel.press(preset);
                for (bool developed : {false, true}) {
                    if (developed && !split) continue;
                    const QRectF part = canvas->framedRect(developed);
                    const QRectF triad = canvas->triadRect(developed);
                    const QString where = QString("station %1 preset %2 developed %3")
                                              .arg(station)
                                              .arg(preset - Qt::Key_0)
                                              .arg(developed);
                    QVERIFY2(!part.intersects(triad), qPrintable(where));
                    QVERIFY(part.width() > 0.4 * canvas->width() / (split ? 2 : 1) ||
                            part.height() > 0.4 * canvas->height());
                }
            }
        }
    }
};

QTEST_MAIN(ToolpathScreenTest)
#include "test_toolpath_screen.moc"
