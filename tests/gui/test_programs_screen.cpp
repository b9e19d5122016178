// Program directory: demo programs listed per station, listing shown, Enter selects.
#include <sys/stat.h>

#include <QLabel>
#include <QListWidget>
#include <QTemporaryDir>
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


    /// Issue 22 §6: what the program loader could not read is in every
    /// station's error window, not only on stderr: a folder and a FIFO named
    /// like programs, and a stale temporary file of a killed save.
    void problemsOfTheProgramFolderAreShownInTheErrorWindow() {
        QTemporaryDir dir;
        writeProgram(QDir(dir.path()), 1, programHeader(1, "Good") + "N0000 G1 X1 F100\nN0001 M30\n");
        QVERIFY(QDir(dir.path()).mkdir("N1010005.DAT"));
        QVERIFY(::mkfifo(QDir(dir.path()).filePath("N1010006.DAT").toLocal8Bit().constData(), 0644) ==
                0);
        mtc::hmi::PanelOptions options;
        options.programsDir = dir.path();
        PanelFixture panel(options);
        QVERIFY(panel.window->showScreen("errors"));
        auto* list = panel.window->screen(0, "errors")->findChild<QListWidget*>("errorList");
        QVERIFY(list);
        QStringList texts;
        for (int row = 0; row < list->count(); ++row)
            texts << list->item(row)->text() + " " + list->item(row)->toolTip();
        const QString all = texts.join('\n');
        QVERIFY2(all.contains("N1010005.DAT is a directory"), qPrintable(all));
        QVERIFY2(all.contains("N1010006.DAT is a FIFO"), qPrintable(all));
        QVERIFY2(!all.contains("N1010001.DAT"), qPrintable(all));  // the good program is no problem
    }
};

QTEST_MAIN(ProgramsScreenTest)
#include "test_programs_screen.moc"
