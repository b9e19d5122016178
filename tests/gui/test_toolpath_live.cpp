// The part cut live on the toolpath screen (issue 19 §3, TP-027): after
// Start (Shift+F5) the view draws the station's part as the tool has cut it,
// not the simulated finished part; it grows with the station's time, stays
// as Control reset (Shift+F7) left it, and a run to the end leaves the
// finished part's volume. Offscreen: the model's part is what the 3D view
// draws (tests/gl draws it).
#include <QLabel>
#include <QRegularExpression>
#include <cmath>

#include "PanelFixture.h"
#include "screens/toolpath/ToolpathModel.h"
#include "screens/toolpath/ToolpathScreen.h"

using mtc::screens::ToolpathScreen;

namespace {

/// The removed volume a part note gives ("... 1234 mm³ removed ..."), or -1.
double removedIn(const QString& note) {
    const QRegularExpressionMatch m =
        QRegularExpression(QStringLiteral("(\\d+) mm³ removed")).match(note);
    return m.hasMatch() ? m.captured(1).toDouble() : -1.0;
}

}  // namespace

class ToolpathLiveTest : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() { useTestSettings(); }

    void thePartIsCutAsTheAxesTravel() {
        PanelFixture panel;
        panel.session->selectProgram(0, 1);
        panel.window->showScreen("toolpath");
        panel.session->setTimerEnabled(false);  // the test gives the station its time
        auto* screen = static_cast<ToolpathScreen*>(panel.window->screen(0, "toolpath"));
        const auto* model = screen->model();
        const QLabel* legend = screen->findChild<QLabel*>("toolpathLegend");
        QVERIFY(!model->partIsLive());
        const QString finishedNote = model->part().note;
        const double finished = removedIn(finishedNote);
        QVERIFY2(finishedNote.startsWith("Finished part") && finished > 0.0,
                 qPrintable(finishedNote));

        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start
        panel.session->advance(0.02);
        QVERIFY(model->partIsLive());
        QVERIFY2(model->part().note.startsWith("Part being cut: 0 mm³"),
                 qPrintable(model->part().note));
        QVERIFY(!model->part().triangles.empty());  // the blank
        QVERIFY(legend->text().contains("Part being cut"));
        // Until the tool has cut something: the view takes the part at most
        // every kLiveMeshMs, so each look waits for its next mesh.
        double cut = 0.0;
        for (int tick = 0; tick < 600 && cut <= 0.0; ++tick) {
            panel.session->advance(0.1);
            if (panel.session->station(0).liveCut().part()->removedVolume() > 0.0)
                QTRY_VERIFY_WITH_TIMEOUT(removedIn(model->part().note) > 0.0,
                                         4 * mtc::screens::ToolpathModel::kLiveMeshMs);
            cut = removedIn(model->part().note);
        }
        QVERIFY2(cut > 0.0 && cut < finished, qPrintable(model->part().note));

        panel.press(Qt::Key_F7, Qt::ShiftModifier);  // Control reset
        panel.session->advance(0.5);
        QTRY_VERIFY_WITH_TIMEOUT(model->part().note.startsWith("Part as the run left it"),
                                 4 * mtc::screens::ToolpathModel::kLiveMeshMs);
        const double stopped = removedIn(model->part().note);
        QVERIFY2(stopped >= cut && stopped < finished, qPrintable(model->part().note));
        panel.session->advance(2.0);
        QCOMPARE(removedIn(model->part().note), stopped);

        // A new Start: a new blank, cut to the end of the program.
        panel.press(Qt::Key_F5, Qt::ShiftModifier);
        panel.session->advance(0.02);
        QCOMPARE(removedIn(model->part().note), 0.0);
        for (int tick = 0; tick < 20000 && panel.session->station(0).busy(); ++tick)
            panel.session->advance(0.25);
        QVERIFY(!panel.session->station(0).busy());
        panel.session->advance(0.02);
        QTRY_VERIFY_WITH_TIMEOUT(model->part().note.startsWith("Part as the run left it"),
                                 4 * mtc::screens::ToolpathModel::kLiveMeshMs);
        // The live tools and offsets are the configuration's: the finished part.
        QVERIFY2(std::abs(removedIn(model->part().note) - finished) <= 1.0,
                 qPrintable(model->part().note + " / " + finishedNote));

        // M hides the part and shows it again.
        QVERIFY(model->partShown());
        panel.press(Qt::Key_M);
        QVERIFY(!model->partShown());
        panel.press(Qt::Key_M);
        QVERIFY(model->partShown());
        QVERIFY(model->partIsLive());
    }

    /// After the run, jogs on the base screen cut on its part (TP-028).
    void jogsAfterTheRunCutOnItsPart() {
        PanelFixture panel;
        panel.session->selectProgram(0, 1);
        panel.window->showScreen("toolpath");
        panel.session->setTimerEnabled(false);
        auto* screen = static_cast<ToolpathScreen*>(panel.window->screen(0, "toolpath"));
        const auto* model = screen->model();
        const mtc::core::Station& mill = panel.session->station(0);
        panel.press(Qt::Key_F5, Qt::ShiftModifier);  // Start
        for (int tick = 0; tick < 20000 && mill.busy(); ++tick)
            panel.session->advance(0.25);
        QVERIFY(!mill.busy());
        const double afterRun = mill.liveCut().part()->removedVolume();

        panel.press(Qt::Key_F3, Qt::ShiftModifier);  // M key Manual
        panel.press(Qt::Key_F11);                    // base screen
        panel.press(Qt::Key_F6);                     // step 10
        // The run ends beside the plate at X-20 Y-20: over it at X20 Y20.
        for (int axis = 0; axis < 2; ++axis) {
            for (int press = 0; press < 4; ++press)
                panel.press(Qt::Key_Plus);
            panel.press(Qt::Key_Down);  // the next axis; Z last
        }
        // Down in steps of 10 mm until the tool is in the material.
        for (int press = 0; press < 40 && mill.liveCut().part()->removedVolume() <= afterRun;
             ++press) {
            panel.press(Qt::Key_Minus);
            for (int tick = 0; tick < 2000 && mill.jogging(); ++tick)
                panel.session->advance(0.02);
        }
        const double jogged = mill.liveCut().part()->removedVolume();
        QVERIFY2(jogged > afterRun, qPrintable(QString::number(jogged)));

        panel.press(Qt::Key_F4);  // toolpath
        QCOMPARE(panel.window->currentScreenName(), QString("toolpath"));
        QTRY_VERIFY_WITH_TIMEOUT(
            model->part().note.startsWith("Part of the run, cut on by MDI and jogging"),
            4 * mtc::screens::ToolpathModel::kLiveMeshMs);
        QVERIFY2(std::abs(removedIn(model->part().note) - jogged) <= 1.0,
                 qPrintable(model->part().note));
    }
};

QTEST_MAIN(ToolpathLiveTest)
#include "test_toolpath_live.moc"
