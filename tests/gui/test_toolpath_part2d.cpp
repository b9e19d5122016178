// The part in the 2D view (TP-030): without OpenGL the view draws the
// material-removal part the 3D view draws, from the same mesh, with the same
// legend; the key M hides and shows it; while the program runs it is the
// part being cut. Offscreen (the 2D view), real keys on the real panel.
#include <QHash>
#include <QLabel>
#include <QSet>
#include <QTest>
#include <cmath>

#include "PanelFixture.h"
#include "screens/toolpath/PainterToolpathCanvas.h"
#include "screens/toolpath/ToolpathModel.h"
#include "screens/toolpath/ToolpathScreen.h"

using mtc::screens::PainterToolpathCanvas;
using mtc::screens::ToolpathScreen;

namespace {

ToolpathScreen* toolpath(PanelFixture& panel, int slot = 0) {
    return static_cast<ToolpathScreen*>(panel.window->screen(slot, "toolpath"));
}

/// Pixels of the part's colour at one of its shades: the brass of the
/// palette times a factor between 0.15 and 1 (light, height), each channel
/// within 3 of it. Nothing else in the view has that hue.
QSet<QRgb> partShades(const QColor& part) {
    QSet<QRgb> shades;
    for (int i = 15; i <= 100; ++i)
        for (int d = -3; d <= 3; ++d)
            shades.insert(qRgb(std::clamp(part.red() * i / 100 + d, 0, 255),
                               std::clamp(part.green() * i / 100 + d, 0, 255),
                               std::clamp(part.blue() * i / 100 + d, 0, 255)));
    return shades;
}

/// How many pixels of `image` are part pixels, and how many of them have
/// the shade most of them have.
std::pair<int, int> partPixels(const QImage& image, const QColor& part) {
    static QSet<QRgb> shades;
    if (shades.isEmpty()) shades = partShades(part);
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    int n = 0;
    QHash<QRgb, int> seen;
    for (int y = 0; y < rgb.height(); ++y)
        for (int x = 0; x < rgb.width(); ++x) {
            const QRgb pixel = rgb.pixel(x, y) | 0xff000000u;
            if (shades.contains(pixel)) {
                ++n;
                ++seen[pixel];
            }
        }
    int most = 0;
    for (int count : seen)
        most = std::max(most, count);
    return {n, most};
}

int differing(const QImage& a, const QImage& b) {
    const QImage p = a.convertToFormat(QImage::Format_RGB32);
    const QImage q = b.convertToFormat(QImage::Format_RGB32);
    int n = 0;
    for (int y = 0; y < p.height(); ++y)
        for (int x = 0; x < p.width(); ++x)
            if (p.pixel(x, y) != q.pixel(x, y)) ++n;
    return n;
}

}  // namespace

class ToolpathPart2dTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { useTestSettings(); }

    /// The mill's cover plate from above (G17): the finished part fills the
    /// plate's area, its pocket floor a darker shade than its top; M hides
    /// it (the legend too) and shows it again, pixel for pixel.
    void theMillsPartIsDrawnAndMHidesIt() {
        PanelFixture panel;
        panel.session->selectProgram(0, 1);
        QVERIFY(panel.window->showScreen("toolpath"));
        ToolpathScreen* screen = toolpath(panel);
        auto* canvas = qobject_cast<PainterToolpathCanvas*>(screen->canvas());
        QVERIFY(canvas);
        const auto* model = screen->model();
        const QLabel* legend = screen->findChild<QLabel*>("toolpathLegend");
        QVERIFY2(model->partShown(), qPrintable(model->part().note));
        QVERIFY2(legend->text().contains(model->part().note + " (M hides)"),
                 qPrintable(legend->text()));
        QVERIFY(legend->text().contains(model->palette().part.name()));  // its swatch
        panel.press(Qt::Key_1);                                          // G17: from above
        const QImage shown = canvas->picture();
        const auto [pixels, top] = partPixels(shown, model->palette().part);
        // The plate (100 x 60 of the 876 x ~500 view framing it) is a good
        // share of the picture; the pocket floor and the contour's steps lie
        // lower than the top: darker shades, a tenth of the part or more.
        QVERIFY2(pixels > shown.width() * shown.height() / 10,
                 qPrintable(QString("%1 of %2").arg(pixels).arg(shown.width() * shown.height())));
        QVERIFY2(top < pixels * 9 / 10, qPrintable(QString("%1 of %2").arg(top).arg(pixels)));

        panel.press(Qt::Key_M);
        QVERIFY(!model->partShown());
        QVERIFY2(!legend->text().contains("(M hides)"), qPrintable(legend->text()));
        const QImage hidden = canvas->picture();
        QVERIFY2(partPixels(hidden, model->palette().part).first < pixels / 50,
                 qPrintable(QString::number(partPixels(hidden, model->palette().part).first)));
        panel.press(Qt::Key_M);
        QVERIFY(model->partShown());
        QVERIFY(canvas->picture() == shown);
    }

    /// TP-027 in the 2D view: after Start the blank is drawn (one flat top:
    /// one shade from above), and the part the run leaves shows its floors
    /// darker.
    void thePartBeingCutIsDrawnWhileTheProgramRuns() {
        PanelFixture panel;
        panel.session->selectProgram(0, 1);
        QVERIFY(panel.window->showScreen("toolpath"));
        panel.session->setTimerEnabled(false);  // the test gives the station its time
        ToolpathScreen* screen = toolpath(panel);
        auto* canvas = qobject_cast<PainterToolpathCanvas*>(screen->canvas());
        QVERIFY(canvas);
        const auto* model = screen->model();
        const QColor brass = model->palette().part;
        panel.press(Qt::Key_1);
        const QImage finished = canvas->picture();

        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start
        panel.session->advance(0.02);
        QVERIFY(model->partIsLive());
        const QLabel* legend = screen->findChild<QLabel*>("toolpathLegend");
        QVERIFY2(legend->text().contains("Part being cut: 0 mm³"), qPrintable(legend->text()));
        const QImage blank = canvas->picture();
        const auto [blankPixels, blankTop] = partPixels(blank, brass);
        QVERIFY2(blankPixels > blank.width() * blank.height() / 10,
                 qPrintable(QString::number(blankPixels)));
        // One flat top (a few pixels blend with text and lines).
        QVERIFY2(blankTop > blankPixels * 98 / 100,
                 qPrintable(QString("%1 of %2").arg(blankTop).arg(blankPixels)));
        QVERIFY(differing(finished, blank) > 2000);

        for (int tick = 0; tick < 20000 && panel.session->station(0).busy(); ++tick)
            panel.session->advance(0.25);
        panel.session->advance(0.02);
        QTRY_VERIFY_WITH_TIMEOUT(model->part().note.startsWith("Part as the run left it"),
                                 4 * mtc::screens::ToolpathModel::kLiveMeshMs);
        const QImage cut = canvas->picture();
        QVERIFY(differing(blank, cut) > 2000);
        const auto [cutPixels, cutTop] = partPixels(cut, brass);  // floors below the top
        QVERIFY2(cutTop < cutPixels * 9 / 10,
                 qPrintable(QString("%1 of %2").arg(cutTop).arg(cutPixels)));
    }

    /// The lathe's shaft seen along Y (G18: Z across, X up): the turned
    /// profile is drawn; M hides it.
    void theLathesTurnedPartIsDrawn() {
        PanelFixture panel;
        panel.window->showStation(1);
        panel.session->selectProgram(1, 1);
        QVERIFY(panel.window->showScreen("toolpath"));
        ToolpathScreen* screen = toolpath(panel, 1);
        auto* canvas = qobject_cast<PainterToolpathCanvas*>(screen->canvas());
        QVERIFY(canvas);
        const auto* model = screen->model();
        QVERIFY2(model->partShown(), qPrintable(model->part().note));
        panel.press(Qt::Key_2);
        const QImage shown = canvas->picture();
        const int pixels = partPixels(shown, model->palette().part).first;
        QVERIFY2(pixels > shown.width() * shown.height() / 20, qPrintable(QString::number(pixels)));
        panel.press(Qt::Key_M);
        QVERIFY(partPixels(canvas->picture(), model->palette().part).first < pixels / 50);
    }
};

QTEST_MAIN(ToolpathPart2dTest)
#include "test_toolpath_part2d.moc"
