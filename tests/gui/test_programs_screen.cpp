// Program directory: demo programs listed per station, listing shown, Enter selects.
#include <QLabel>
#include <QListView>
#include <QPlainTextEdit>

#include "PanelFixture.h"

class ProgramsScreenTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { useTestSettings(); }

    void showsTheStationsProgramsWithListing() {
        PanelFixture panel;
        QVERIFY(panel.window->showScreen("programs"));
        auto* list = panel.window->screen(0, "programs")->findChild<QListView*>("programList");
        QVERIFY(list);
        QVERIFY(list->model()->rowCount() >= 2);
        QVERIFY(list->model()->index(0, 0).data().toString().contains("N1010001.DAT"));
        auto* listing =
            panel.window->screen(0, "programs")->findChild<QPlainTextEdit*>("programListing");
        QVERIFY(listing->toPlainText().contains("%NPG"));
        QVERIFY(listing->toPlainText().contains("PROGRAMMENDE"));
        panel.press(Qt::Key_Down);
        QVERIFY(listing->toPlainText().contains(
            list->model()->index(1, 0).data().toString().section(' ', -1)));
    }

    void enterSelectsTheProgramForThisStationOnly() {
        PanelFixture panel;
        QVERIFY(panel.window->showScreen("programs"));
        panel.press(Qt::Key_Return);
        QCOMPARE(panel.session->control(0).selectedProgram(), 1);
        QCOMPARE(panel.session->control(1).selectedProgram(), 0);
        QCOMPARE(panel.window->findChild<QLabel*>("headerProgram")->text(), QString("Program: 1"));
        auto* list = panel.window->screen(0, "programs")->findChild<QListView*>("programList");
        QVERIFY(list->model()->index(0, 0).data().toString().startsWith("→"));
    }

    void softKeyF1SelectsOnTheLathe() {
        PanelFixture panel;
        panel.press(Qt::Key_PageDown, Qt::ControlModifier);
        QVERIFY(panel.window->showScreen("programs"));
        // Lathe programs in number order: 1, 2 (GNE demo), 99.
        panel.press(Qt::Key_Down);
        panel.press(Qt::Key_Down);
        panel.press(Qt::Key_F1);
        QCOMPARE(panel.session->control(1).selectedProgram(), 99);
        QCOMPARE(panel.session->control(0).selectedProgram(), 0);
    }
};

QTEST_MAIN(ProgramsScreenTest)
#include "test_programs_screen.moc"
