// The 3D toolpath view on a real X server (xvfb-run, xcb, Mesa llvmpipe):
// VTK renders the path (the picture is not blank and shows the colours of
// the motion types), the highlighted block's colour appears, picking a
// segment with the mouse selects its block and back, the G32 program shows
// the developed plane and the wrapped cylinder side by side, and renders
// are coalesced. A compensated program shows its programmed contour beside
// the tool-centre path, with a legend entry. A 200,000-segment program moves with a coarse copy
// within the cell budget, and picking on that copy still selects the right block.
// (While a program runs: test_toolpath_gl_running.) The labels name the zero
// offset of the block shown and read workpiece coordinates. A path that
// retraces itself draws each line once. The finished part is drawn; M
// hides it.
#include <QDir>
#include <QLabel>
#include <QSet>
#include <QTemporaryDir>
#include <cmath>
#include <cstdio>

#include "ToolpathGlSupport.h"
#include "screens/toolpath/ToolpathModel.h"

using mtc::screens::ToolpathScreen;
using mtc::screens::VtkToolpathCanvas;

namespace {

int distinctColours(const QImage& image) {
    QSet<QRgb> seen;
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    for (int y = 0; y < rgb.height(); y += 2)
        for (int x = 0; x < rgb.width(); x += 2)
            seen.insert(rgb.pixel(x, y));
    return seen.size();
}

/// Program `number` of `segments` blocks over the mill's stock (X-150..-50,
/// Y-80..-20, so the view's centre is on the path): 0.25 mm feed moves in
/// 100 mm passes 0.12 mm apart, every 100th block a rapid, with a 0.004 mm
/// wiggle across the pass (under the coarse copy's tolerance).
QString largeProgram(int number, int segments) {
    QString text = QString(
                       "iMTc/01%1/01.00/0000000000/21.11.2026/19:00:00/N1010%1.DAT/1\n"
                       "%NPG:1:01:0:%1\n!01.00\n#01Large path\n$\n$\n$\n$\n*Large path\n%NPG\n")
                       .arg(number, 3, 10, QChar('0'));
    std::string blocks = "N0000 G0 G17 G90 G94 X-150 Y-80 Z-120\n";
    blocks.reserve(static_cast<std::size_t>(segments) * 36);
    char line[64];
    for (int i = 1; i <= segments; ++i) {
        const int pass = (i - 1) / 400, step = (i - 1) % 400 + 1;
        const double x = pass % 2 ? -50.0 - step * 0.25 : -150.0 + step * 0.25;
        const double y = -80.0 + pass * 0.12 + (i % 2) * 0.004;
        const int n = std::snprintf(line, sizeof line, "N%04d %s X%.3f Y%.3f\n", i % 10000,
                                    i % 100 == 0 ? "G0" : "G1 F1000", x, y);
        blocks.append(line, static_cast<std::size_t>(n));
    }
    return text + QString::fromStdString(blocks) + "N9999 M30\n";
}

/// Program `number`: a 60 x 40 rectangle with rounded corners (R10 arcs)
/// at Z-121, `laps` times over, every other lap the other way round.
QString lapsProgram(int number, int laps) {
    QString text = QString(
                       "iMTc/01%1/01.00/0000000000/27.11.2026/07:00:00/N1010%1.DAT/1\n"
                       "%NPG:1:01:0:%1\n!01.00\n#01Laps\n$\n$\n$\n$\n*Laps\n%NPG\n")
                       .arg(number, 3, 10, QChar('0'));
    text += "N0001 G0 G17 G90 X-130 Y-70 Z-110\nN0002 G1 Z-121 F800\n";
    const char* forward =
        "G1 X-80\nG3 X-70 Y-60 I-80 J-60\nG1 Y-40\nG3 X-80 Y-30 I-80 J-40\nG1 X-120\n"
        "G3 X-130 Y-40 I-120 J-40\nG1 Y-60\nG3 X-120 Y-70 I-120 J-60\nG1 X-130\n";
    const char* backward =
        "G1 X-120\nG2 X-130 Y-60 I-120 J-60\nG1 Y-40\nG2 X-120 Y-30 I-120 J-40\nG1 X-80\n"
        "G2 X-70 Y-40 I-80 J-40\nG1 Y-60\nG2 X-80 Y-70 I-80 J-60\nG1 X-130\n";
    for (int lap = 0; lap < laps; ++lap)
        text += lap % 2 == 0 ? forward : backward;
    return text + "G0 Z-110\nM30\n";
}

/// Program `number`: an 80 x 50 rectangle milled outside with T4 (radius 8)
/// under G41, clockwise: the tool centre runs 8 mm outside the contour.
QString compensatedProgram(int number) {
    return QString(
               "iMTc/01%1/01.00/0000000000/26.11.2026/03:00:00/N1010%1.DAT/1\n"
               "%NPG:1:01:0:%1\n!01.00\n#01Compensated\n$\n$\n$\n$\n*Compensated\n"
               "%NPG\n")
               .arg(number, 3, 10, QChar('0')) +
           "N0001 T4 S1000 M3\nN0002 G0 G17 G90 G54 X0 Y-20 Z5\nN0003 G1 Z-2 F500\n"
           "N0004 G41 X10 Y0\nN0005 Y50\nN0006 X90\nN0007 Y0\nN0008 X10\n"
           "N0009 G40 X0 Y-20\nN0010 G0 Z5\nN0011 M30\n";
}

}  // namespace

class ToolpathGlTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { useTestSettings(); }

    void vtkViewRendersThePathInItsColours() {
        PanelFixture panel;
        panel.session->selectProgram(0, 1);
        QVERIFY(panel.window->showScreen("toolpath"));
        ToolpathScreen* screen = toolpath(panel);
        QVERIFY2(screen->findChild<QWidget*>("toolpathVtkWidget"), "3D view under X");
        VtkToolpathCanvas* canvas = vtkCanvas(screen);
        QVERIFY(canvas);
        const QImage picture = canvas->picture();
        QVERIFY(picture.width() > 300);
        QVERIFY2(distinctColours(picture) > 20, "the view is not blank");
        const auto& palette = screen->model()->palette();
        QVERIFY(count(picture, palette.feed) > 50);
        QVERIFY(count(picture, palette.rapid) > 20);
        QVERIFY(count(picture, palette.highlight) == 0);
        panel.press(Qt::Key_PageDown);
        panel.press(Qt::Key_PageDown);
        QVERIFY(!screen->model()->highlighted().empty());
        QVERIFY2(count(canvas->picture(), palette.highlight) > 20, "highlighted block shown");
    }

    void compensatedProgramShowsContourAndToolCentrePath() {
        QTemporaryDir dir;
        writeProgram(QDir(dir.path()), 8, compensatedProgram(8));
        writeProgram(QDir(dir.path()), 7, largeProgram(7, 20));  // the same, uncompensated
        mtc::hmi::PanelOptions options;
        options.programsDir = dir.path();
        PanelFixture panel(options);
        VtkToolpathCanvas* canvas = nullptr;
        ToolpathScreen* screen = showToolpathOf(panel, 8, canvas);
        QVERIFY(canvas);
        auto* model = screen->model();
        QVERIFY2(model->geometry(), qPrintable(model->summary()));
        QVERIFY(model->geometry()->contour.segmentCount() >= 4);
        // The finished part's walls (a z-map: slanted over one cell) lie
        // over the contour at their foot; the lines are what is tested here.
        QTest::keyClick(screen, Qt::Key_M);
        QVERIFY(!model->partShown());
        QTest::keyClick(screen, Qt::Key_1);  // from above
        canvas->renderNow();
        const QImage picture = canvas->picture();
        const auto& palette = model->palette();
        QVERIFY2(count(picture, palette.contour) > 100, "the programmed contour is drawn");
        QVERIFY2(count(picture, palette.feed) > 100, "the tool-centre path is drawn");
        auto* legend = screen->findChild<QLabel*>("toolpathLegend");
        QVERIFY(legend);
        QVERIFY2(legend->text().contains("programmed contour"), qPrintable(legend->text()));
        QVERIFY(legend->text().contains(palette.contour.name()));
        // Without compensation: no contour layer, no contour colour, no legend entry.
        panel.session->selectProgram(0, 7);
        model->refresh();
        QVERIFY(model->geometry());
        QCOMPARE(model->geometry()->contour.segmentCount(), std::size_t{0});
        canvas->renderNow();
        QCOMPARE(count(canvas->picture(), palette.contour), 0);
        QVERIFY(!legend->text().contains("programmed contour"));
    }

    void pickingSelectsTheBlockAndTheRestartCursor() {
        PanelFixture panel;
        panel.session->selectProgram(0, 1);
        panel.press(Qt::Key_F1, Qt::ShiftModifier);  // restart screen on program 1
        panel.window->showScreen("toolpath");
        ToolpathScreen* screen = toolpath(panel);
        VtkToolpathCanvas* canvas = vtkCanvas(screen);
        QVERIFY(canvas);
        panel.press(Qt::Key_1);  // G17 view from above
        canvas->renderNow();
        auto* model = screen->model();
        const auto& g = *model->geometry();
        auto* vtkWidget = screen->findChild<QWidget*>("toolpathVtkWidget");
        int hits = 0;
        for (long m = 1; m < static_cast<long>(g.moves.size()) && hits < 3; m += 3) {
            if (g.moves[static_cast<std::size_t>(m)].kind == mtc::core::ToolpathKind::Rapid)
                continue;
            const auto at = canvas->positionOfMove(m);
            if (!at) continue;
            QTest::mouseClick(vtkWidget, Qt::LeftButton, {}, vtkWidget->mapFrom(canvas, *at));
            if (model->highlighted().empty()) continue;
            const auto& picked = g.moves[model->highlighted().front()];
            if (picked.block != g.moves[static_cast<std::size_t>(m)].block) continue;
            ++hits;
        }
        QVERIFY2(hits >= 2, "clicks on segments select their blocks");
        // Round trip: the restart cursor (target before Enter) is on the picked block.
        const auto [first, last] = g.sceneRange(model->highlighted().front());
        QVERIFY(first < last);
        const auto expected = g.scene.vertex(g.scene.segmentStart[first]);
        const auto marks = model->marks();
        QVERIFY(marks.hasTarget);
        for (std::size_t i = 0; i < 3; ++i)
            QCOMPARE(marks.target[i], expected[i]);
    }

    void cylinderProgramShowsDevelopedPlaneAndCylinder() {
        PanelFixture panel;
        panel.window->showStation(1);
        panel.session->selectProgram(1, 1);
        panel.window->showScreen("toolpath");
        ToolpathScreen* screen = toolpath(panel, 1);
        VtkToolpathCanvas* canvas = vtkCanvas(screen);
        QVERIFY(canvas);
        const QImage picture = canvas->picture();
        const auto& palette = screen->model()->palette();
        // Both halves show path colours: developed plane left, cylinder right.
        const QImage left = picture.copy(0, 0, picture.width() / 2, picture.height());
        const QImage right =
            picture.copy(picture.width() / 2, 0, picture.width() / 2, picture.height());
        QVERIFY(count(left, palette.feed) + count(left, palette.arc) > 20);
        QVERIFY(count(right, palette.feed) + count(right, palette.arc) +
                    count(right, palette.rapid) >
                20);
    }

    void rendersAreCoalescedAndMovingUsesLevelOfDetail() {
        PanelFixture panel;
        panel.session->selectProgram(0, 1);
        panel.window->showScreen("toolpath");
        VtkToolpathCanvas* canvas = vtkCanvas(toolpath(panel));
        QVERIFY(canvas);
        canvas->renderNow();
        const int before = canvas->renderCount();
        for (int i = 0; i < 10; ++i)
            panel.press(Qt::Key_Left);  // ten rotations in one event-loop pass
        QTRY_VERIFY(canvas->renderCount() > before);
        QVERIFY(canvas->renderCount() <= before + 10);
        QTRY_VERIFY(!canvas->showingLevelOfDetail());  // full detail once still
    }

    void largeProgramMovesWithACoarseCopyThatPicksTheRightBlock() {
        QTemporaryDir dir;
        writeProgram(QDir(dir.path()), 9, largeProgram(9, 200000));
        mtc::hmi::PanelOptions options;
        options.programsDir = dir.path();
        PanelFixture panel(options);
        VtkToolpathCanvas* canvas = nullptr;
        ToolpathScreen* screen = showToolpathOf(panel, 9, canvas);
        QVERIFY(canvas);
        auto* model = screen->model();
        QVERIFY2(model->geometry(), qPrintable(model->summary()));
        const auto& g = *model->geometry();
        QVERIFY(g.scene.segmentCount() >= 200000);  // and the approach
        QVERIFY(canvas->levelOfDetailCells() > 0);
        QVERIFY2(canvas->levelOfDetailCells() <= VtkToolpathCanvas::kLevelOfDetailCells,
                 qPrintable(QString::number(canvas->levelOfDetailCells())));
        // From above, then zoomed in until a segment is ~10 pixels long.
        QTest::keyClick(screen, Qt::Key_1);
        for (int i = 0; i < 10; ++i)
            QTest::keyClick(screen, Qt::Key_Plus);
        QVERIFY(canvas->showingLevelOfDetail());
        canvas->renderNow();
        auto* vtkWidget = screen->findChild<QWidget*>("toolpathVtkWidget");
        int hits = 0, tries = 0;
        for (long m = 1; m < static_cast<long>(g.moves.size()) && tries < 8; m += 7) {
            if (g.moves[static_cast<std::size_t>(m)].kind == mtc::core::ToolpathKind::Rapid)
                continue;
            const auto at = canvas->positionOfMove(m);
            if (!at) continue;
            ++tries;
            QTest::mouseClick(vtkWidget, Qt::LeftButton, {}, vtkWidget->mapFrom(canvas, *at));
            QVERIFY(!model->highlighted().empty());
            QCOMPARE(g.moves[model->highlighted().front()].block,
                     g.moves[static_cast<std::size_t>(m)].block);
            ++hits;
        }
        QVERIFY2(hits >= 3, "clicks on segments in the zoomed view");
        QCOMPARE(canvas->picksOnLevelOfDetail(), hits);  // each click started a move: coarse
        QTRY_VERIFY(!canvas->showingLevelOfDetail());
    }

    /// TP-019: the tick labels read workpiece coordinates of the zero offset
    /// of the block shown and the caption names it; going from a G54 block
    /// to a G55 block relabels, and the kept steady picture (TP-018) shows
    /// the new labels, not the old ones.
    void ticksAndCaptionFollowTheZeroOffsetOfTheBlockShown() {
        PanelFixture panel;
        // Demo mill: G54 = X-150 Y-80 Z-120, G55 = X50 Y-80 Z-120.
        panel.session->addProgram(0, 50, "two-vices.nc",
                                  "N0001 G54 G0 X5 Y5 Z5\nN0002 G1 Z-2 F2000\nN0003 X40\n"
                                  "N0004 G0 Z5\nN0005 G55 G0 X5 Y5\nN0006 G1 Z-2\n"
                                  "N0007 X40\nN0008 G0 Z5\nN0009 M30\n");
        VtkToolpathCanvas* canvas = nullptr;
        ToolpathScreen* screen = showToolpathOf(panel, 50, canvas);
        QVERIFY(canvas);
        panel.press(Qt::Key_PageDown);  // N0001 G54 G0 ...
        canvas->picture();
        QVERIFY2(canvas->sceneCaption().contains("Workpiece coordinates G54,\nzero point at "
                                                 "machine X-150.000 Y-80.000 Z-120.000"),
                 qPrintable(canvas->sceneCaption()));
        const auto xInG54 = canvas->tickRange(0), zInG54 = canvas->tickRange(2);
        for (int i = 0; i < 4; ++i)
            panel.press(Qt::Key_PageDown);  // N0005 G55 G0 X5 Y5
        QVERIFY(screen->model()->highlightText().contains("N0005"));
        QVERIFY2(canvas->sceneCaption().contains("Workpiece coordinates G55,\nzero point at "
                                                 "machine X50.000 Y-80.000 Z-120.000"),
                 qPrintable(canvas->sceneCaption()));
        // The box stays, its X ticks read 200 mm less (G54 X-150 -> G55 X50), Z the same.
        QVERIFY(std::abs(canvas->tickRange(0)[0] - (xInG54[0] - 200.0)) < 1e-9);
        QVERIFY(std::abs(canvas->tickRange(0)[1] - (xInG54[1] - 200.0)) < 1e-9);
        QVERIFY(canvas->tickRange(2) == zInG54);
        const int keptBefore = canvas->keptRenders();
        canvas->picture();
        canvas->picture();
        const QImage kept = canvas->picture();
        QVERIFY(canvas->keptRenders() > keptBefore);
        canvas->keepSteadyPicture(false);
        const QImage full = canvas->picture();
        QCOMPARE(kept.convertToFormat(QImage::Format_RGB32),
                 full.convertToFormat(QImage::Format_RGB32));
    }

    /// TP-026: the caption and the axes triad do not cover each other, and
    /// the caption's text grows with the screen's dpi like the lines.
    void theCaptionKeepsClearOfTheTriadAndGrowsWithTheDpi() {
        PanelFixture panel;
        VtkToolpathCanvas* canvas = nullptr;
        showToolpathOf(panel, 1, canvas);
        QVERIFY(canvas);
        double ratio = 1.0;
        int expected = 1;
        lineWidthAtScale(*canvas, ratio, expected);
        if (QTest::currentTestFailed()) return;
        canvas->renderNow();
        const QRect caption = canvas->sceneCaptionRect();
        const QRect triad = canvas->triadRect();
        QVERIFY2(!caption.isEmpty() && !triad.isEmpty(), "both drawn");
        QVERIFY2(!caption.intersects(triad),
                 qPrintable(QString("caption %1,%2 %3x%4 triad %5,%6 %7x%8")
                                .arg(caption.x())
                                .arg(caption.y())
                                .arg(caption.width())
                                .arg(caption.height())
                                .arg(triad.x())
                                .arg(triad.y())
                                .arg(triad.width())
                                .arg(triad.height())));
        QVERIFY2(canvas->rect().adjusted(-1, -1, 1, 1).contains(caption),
                 qPrintable(QString("caption %1,%2 %3x%4 in %5x%6")
                                .arg(caption.x())
                                .arg(caption.y())
                                .arg(caption.width())
                                .arg(caption.height())
                                .arg(canvas->width())
                                .arg(canvas->height())));
        // Device pixels a caption line takes: 14-pixel text at 96 dpi.
        const int lines = canvas->sceneCaption().count('\n') + 1;
        const double lineHeight = caption.height() * ratio / lines;
        const double scale = expected == 2 ? 1.5 : 1.0;
        QVERIFY2(lineHeight >= 14.0 * scale * 0.9 && lineHeight <= 14.0 * scale * 1.6,
                 qPrintable(QString("%1 px a line at scale %2").arg(lineHeight).arg(scale)));
    }

    /// TP-014: every preset view of both demo machines frames the part
    /// above the caption, which fits its picture area; in a plane view whose box stands over the
    /// caption, the tick labels and title under its bottom edge (two rows of
    /// 10-pixel text 20 pixels apart at 96 dpi) fit between the two.
    void theFramedPartStaysAboveTheCaptionInEveryView() {
        for (const int slot : {0, 1}) {
            PanelFixture panel;
            panel.window->showStation(slot);
            panel.session->selectProgram(slot, 1);
            QVERIFY(panel.window->showScreen("toolpath"));
            ToolpathScreen* screen = toolpath(panel, slot);
            VtkToolpathCanvas* canvas = vtkCanvas(screen);
            QVERIFY(canvas);
            const int labels = static_cast<int>(
                std::ceil(60.0 * canvas->deviceLineScale() / canvas->devicePixelRatioF()));
            for (const Qt::Key preset : {Qt::Key_1, Qt::Key_2, Qt::Key_3, Qt::Key_4}) {
                panel.press(preset);
                canvas->renderNow();
                const QRect caption = canvas->sceneCaptionRect();
                const QRect part = canvas->framedRect();
                QVERIFY(!part.isEmpty() && !caption.isEmpty());
                // Beside a developed plane too, the caption fits its half.
                QVERIFY2(canvas->rect().adjusted(-1, -1, 1, 1).contains(caption),
                         qPrintable(QString("station %1: caption right %2 of %3")
                                        .arg(slot)
                                        .arg(caption.right())
                                        .arg(canvas->width())));
                // A plane view labels the box's bottom edge across its width.
                const bool over = preset != Qt::Key_4 && part.left() <= caption.right() + labels;
                QVERIFY2(part.bottom() < caption.top() &&
                             (!over || part.bottom() + labels <= caption.top()),
                         qPrintable(QString("station %1 view %2: part bottom %3, caption top %4")
                                        .arg(slot)
                                        .arg(preset - Qt::Key_0)
                                        .arg(part.bottom())
                                        .arg(caption.top())));
            }
        }
    }

    /// TP-020: the demo lathe programs radii (B015 = radius) and says so on
    /// its X axis; a G16 block is read in diameters: ticks twice the radius.
    void theLatheXReadsTheDiameterUnderG16AndSaysRadiusOtherwise() {
        PanelFixture panel;
        panel.window->showStation(1);
        // Demo lathe: G54 = X0 Z255.5; X is the scene's X, Z its Z.
        panel.session->addProgram(1, 50, "diameter.nc",
                                  "N0001 G54 G0 X45 Z5\nN0002 G1 Z-30 F200\nN0003 G16\n"
                                  "N0004 G1 X70 Z-40\nN0005 G0 X100\nN0006 M30\n");
        panel.session->selectProgram(1, 50);
        QVERIFY(panel.window->showScreen("toolpath"));
        ToolpathScreen* screen = toolpath(panel, 1);
        VtkToolpathCanvas* canvas = vtkCanvas(screen);
        QVERIFY(canvas);
        panel.press(Qt::Key_PageDown);  // N0001: radius programming
        QVERIFY(screen->model()->highlightText().contains("N0001"));
        canvas->picture();
        QCOMPARE(canvas->axisTitle(0), QString("X (mm, radius, G54)"));
        QCOMPARE(canvas->axisTitle(2), QString("Z (mm, G54)"));
        const auto xRadius = canvas->tickRange(0), zRadius = canvas->tickRange(2);
        for (int i = 0; i < 5 && !screen->model()->highlightText().contains("N0004"); ++i)
            panel.press(Qt::Key_PageDown);  // on to N0004 under G16 (PgDn steps moves)
        QVERIFY(screen->model()->highlightText().contains("N0004"));
        canvas->picture();
        QCOMPARE(canvas->axisTitle(0), QString::fromUtf8("X (mm, \u00d8, G54)"));
        // The same box: X ticks read twice the radius, Z unchanged.
        QVERIFY(std::abs(canvas->tickRange(0)[0] - 2 * xRadius[0]) < 1e-9);
        QVERIFY(std::abs(canvas->tickRange(0)[1] - 2 * xRadius[1]) < 1e-9);
        QVERIFY(xRadius[1] > xRadius[0]);
        QVERIFY(canvas->tickRange(2) == zRadius);
    }

    /// TP-026: the path is one pixel wide at 96 dpi and two at 144 dpi
    /// (ctest runs this again with QT_FONT_DPI=144 and QT_SCALE_FACTOR=1.5).
    void theLinesGrowWithTheScreensDpi() {
        PanelFixture panel;
        panel.session->addProgram(0, 50, "line.nc",
                                  "N0001 G54 G0 X0 Y30 Z5\nN0002 G1 Z-2 F500\nN0003 X100\n"
                                  "N0004 M30\n");
        VtkToolpathCanvas* canvas = nullptr;
        ToolpathScreen* screen = showToolpathOf(panel, 50, canvas);
        QVERIFY(canvas);
        panel.press(Qt::Key_1);  // G17: the X move is a horizontal line
        double ratio = 1.0;
        int expected = 1;
        lineWidthAtScale(*canvas, ratio, expected);
        if (QTest::currentTestFailed()) return;
        const QImage picture = canvas->picture().convertToFormat(QImage::Format_RGB32);
        const auto middle = canvas->positionOfMove(2);
        QVERIFY(middle);
        const int column = static_cast<int>(std::lround(middle->x() * ratio));
        const QColor feed = screen->model()->palette().feed;
        int rows = 0;
        for (int y = 0; y < picture.height(); ++y) {
            const QColor c(picture.pixel(column, y));
            if (std::abs(c.red() - feed.red()) + std::abs(c.green() - feed.green()) +
                    std::abs(c.blue() - feed.blue()) <
                40)
                ++rows;
        }
        QCOMPARE(rows, expected);
    }

    /// TP-018: a station change that shows nothing new (here a dwell: the
    /// machine's time goes on, the axes stand) renders nothing; the axes
    /// moving again do.
    // A path that retraces itself draws each line once (TP-022): 40 laps
    // have the cells of one lap each way and look like two laps.
    void aRetracedPathDrawsEachLineOnceAndLooksTheSame() {
        QTemporaryDir dir;
        writeProgram(QDir(dir.path()), 11, lapsProgram(11, 2));
        writeProgram(QDir(dir.path()), 12, lapsProgram(12, 40));
        mtc::hmi::PanelOptions options;
        options.programsDir = dir.path();
        PanelFixture panel(options);
        QImage pictures[2];
        std::size_t cells[2] = {0, 0}, segments[2] = {0, 0};
        for (int i = 0; i < 2; ++i) {
            panel.session->selectProgram(0, 11 + i);
            QVERIFY(panel.window->showScreen("toolpath"));
            ToolpathScreen* screen = toolpath(panel);
            VtkToolpathCanvas* canvas = vtkCanvas(screen);
            QVERIFY(canvas);
            QTRY_VERIFY(screen->model()->geometry() && screen->model()->programNumber() == 11 + i);
            canvas->renderNow();
            pictures[i] = canvas->picture();
            cells[i] = canvas->fullCells();
            segments[i] = screen->model()->geometry()->scene.segmentCount();
            QVERIFY(panel.window->showScreen("position"));
        }
        QVERIFY2(segments[1] > 15 * segments[0], qPrintable(QString::number(segments[1])));
        QVERIFY2(cells[0] > 8 && cells[0] < segments[0], qPrintable(QString::number(cells[0])));
        QCOMPARE(cells[1], cells[0]);  // 38 more laps: no cell more
        // The same lines on the screen (the caption's lines may shift the
        // frame by a pixel or two, so the feed pixels are counted).
        const QColor feed = toolpath(panel)->model()->palette().feed;
        const int two = count(pictures[0], feed), forty = count(pictures[1], feed);
        QVERIFY2(two > 200 && std::abs(forty - two) < two / 20,
                 qPrintable(QString("%1 / %2").arg(two).arg(forty)));
    }

    // The finished part (TP-023): the demo mill's cover plate cut by its
    // program is drawn in the 3D view; M hides it and shows it again.
    void theFinishedPartIsDrawnAndTheKeyMHidesIt() {
        PanelFixture panel;
        VtkToolpathCanvas* canvas = nullptr;
        ToolpathScreen* screen = showToolpathOf(panel, 1, canvas);
        QVERIFY(canvas);
        auto* model = screen->model();
        QVERIFY2(model->partShown(), qPrintable(model->part().note));
        QVERIFY2(model->part().note.contains("removed"), qPrintable(model->part().note));
        auto* legend = screen->findChild<QLabel*>("toolpathLegend");
        QVERIFY(legend && legend->text().contains("Finished part"));
        canvas->renderNow();
        const QImage withPart = canvas->picture();
        QTest::keyClick(screen, Qt::Key_M);
        QVERIFY(!model->partShown());
        canvas->renderNow();
        const QImage without = canvas->picture();
        QCOMPARE(without.size(), withPart.size());
        int changed = 0;
        for (int y = 0; y < without.height(); y += 2)
            for (int x = 0; x < without.width(); x += 2)
                if (without.pixel(x, y) != withPart.pixel(x, y)) ++changed;
        QVERIFY2(changed > 2000, qPrintable(QString::number(changed)));  // the plate's area
        QTest::keyClick(screen, Qt::Key_M);
        QVERIFY(model->partShown());
        canvas->renderNow();
        QVERIFY(canvas->picture() == withPart);
    }
};

QTEST_MAIN(ToolpathGlTest)
#include "test_toolpath_gl.moc"
