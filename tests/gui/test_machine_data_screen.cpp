// Machine data screen by keys: the page table with the → cursor, page and
// sub selection, editing with range and type checks, GUI write protection,
// the password prompt, live values, and the data file of the panel.
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QTableView>
#include <QTemporaryDir>

#include "PanelFixture.h"
#include "cnc_core/machine_data/MachineDataStore.h"
#include "cnc_core/machine_data/SharedMachineDataFile.h"
#include "cnc_core/machine_data/StandardPages.h"
#include "screens/machine_data/MachineDataTexts.h"

namespace {

using mtc::core::MachineDataStatus;

struct MachineDataPanel : PanelFixture {
    using PanelFixture::PanelFixture;
    mtc::hmi::Screen* screen = nullptr;

    bool open(int station = 0) {
        window->showStation(station);
        if (!window->showScreen("machine-data")) return false;
        screen = window->screen(station, "machine-data");
        return screen != nullptr;
    }
    QAbstractItemModel* table() const { return screen->findChild<QTableView*>("mdTable")->model(); }
    QString cell(int row, int column) const {
        return table()->index(row, column).data().toString();
    }
    QString message() const { return screen->findChild<QLabel*>("mdMessage")->text(); }
    QString header() const { return screen->findChild<QLabel*>("mdPage")->text(); }
    QLineEdit* editor() const { return screen->findChild<QLineEdit*>("mdEditor"); }
    void down(int times) {
        for (int i = 0; i < times; ++i)
            press(Qt::Key_Down);
    }
    /// Types `text` into the focused widget and confirms with Enter.
    void enter(const QString& text) {
        QTest::keyClicks(QApplication::focusWidget(), text);
        press(Qt::Key_Return);
    }
    double value(int page, int process, int sub, int element) const {
        double v = -1;
        session->machineData().read({page, process, sub, element}, v);
        return v;
    }
};

}  // namespace

class MachineDataScreenTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { useTestSettings(); }

    void tableWithCursorAndPages() {
        MachineDataPanel panel;
        QVERIFY(panel.open());
        QVERIFY(panel.header().contains("Page 30"));
        QCOMPARE(panel.table()->rowCount(), 14);
        QCOMPARE(panel.table()->headerData(0, Qt::Horizontal).toString(), QString("Nr."));
        QCOMPARE(panel.cell(0, 0), QString("\u2192001"));
        QCOMPARE(panel.cell(2, 1), QString("Amplification"));
        QCOMPARE(panel.cell(2, 2), QString("0.10"));
        QCOMPARE(panel.cell(2, 3), QString("1/s"));
        panel.down(6);
        QCOMPARE(panel.cell(6, 0), QString("\u2192007"));
        QCOMPARE(panel.cell(0, 0), QString(" 001"));
        panel.press(Qt::Key_Right);
        QVERIFY(panel.header().contains("Page 60"));
        QCOMPARE(panel.cell(3, 2), QString("30"));
        panel.press(Qt::Key_Right);
        QVERIFY(panel.header().contains("sub 1: M(16) functions"));
        QCOMPARE(panel.table()->rowCount(), 40);
        panel.press(Qt::Key_F3);  // soft key: M(16) / Q
        QVERIFY(panel.header().contains("sub 2: Q functions"));
        panel.press(Qt::Key_Right);
        QVERIFY2(panel.header().contains("Page 30"), "the mill has no user page");
        panel.press(Qt::Key_Left);
        QVERIFY(panel.header().contains("Page 61"));
    }

    void germanPageTitlesAndElementNames() {
        mtc::hmi::PanelOptions options;
        options.language = "de";
        MachineDataPanel panel(options);
        QVERIFY(panel.open());
        QVERIFY2(panel.header().contains("30  Adaptive Vorschubregelung"),
                 qPrintable(panel.header()));
        QCOMPARE(panel.cell(2, 1), QString("Verstärkung"));
        panel.press(Qt::Key_Right);
        QVERIFY2(panel.header().contains("60  Satzvorlauf und Wiederanfahren (REPOS)"),
                 qPrintable(panel.header()));
        QCOMPARE(panel.cell(1, 1), QString("Rundachsbetrieb Spindel 2"));
        QCOMPARE(panel.cell(5, 1), QString("T-Nr. Werkzeugspindel 2"));
        panel.press(Qt::Key_Right);
        QVERIFY2(panel.header().contains("M(16)-Funktionen"), qPrintable(panel.header()));
        QCOMPARE(panel.cell(39, 1), QString("Hilfsfunktion 40"));
        // Every name of the core's standard pages has its German text.
        QStringList untranslated;
        for (const mtc::core::MachineDataPage& page :
             {mtc::core::adaptiveFeedPage(), mtc::core::restartPage(),
              mtc::core::functionBufferPage()}) {
            std::vector<std::string> names = page.subTitles;
            names.push_back(page.title);
            for (const auto& element : page.elements)
                names.push_back(element.designation);
            for (const std::string& name : names)
                if (mtc::screens::machineDataText(name) == QString::fromStdString(name))
                    untranslated << QString::fromStdString(name);
        }
        QVERIFY2(untranslated.isEmpty(), qPrintable(untranslated.join("; ")));
    }

    void lathePageFollowsTheStation() {
        MachineDataPanel panel;
        QVERIFY(panel.open(1));
        QVERIFY(panel.header().contains("process 1"));
        panel.press(Qt::Key_Left);
        QVERIFY(panel.header().contains("Page 180"));
        QVERIFY(panel.header().contains("parts transfer"));
        panel.down(1);
        panel.press(Qt::Key_Return);
        panel.enter("612.25");
        QCOMPARE(panel.value(180, 1, 0, 2), 612.25);
        QCOMPARE(panel.cell(1, 2), QString("612.25"));
        QCOMPARE(panel.value(180, 1, 0, 1), 0.0);
    }

    void protectedElementIsNotEdited() {
        MachineDataPanel panel;
        QVERIFY(panel.open());
        panel.press(Qt::Key_Return);  // element 001: protected for the GUI
        QVERIFY(panel.editor()->isHidden());
        QVERIFY(panel.message().contains("write-protected"));
        panel.down(10);  // 011 current feed reduction
        panel.press(Qt::Key_F4);
        QVERIFY(panel.editor()->isHidden());
        QVERIFY(panel.message().contains("011 Current feed reduction"));
    }

    void passwordPromptThenUnlocked() {
        MachineDataPanel panel;
        QVERIFY(panel.open());
        panel.down(9);  // 010 limiting machining torque
        panel.press(Qt::Key_Return);
        QVERIFY(panel.editor()->isVisible());
        QCOMPARE(panel.editor()->text(), QString("0.0"));
        panel.editor()->clear();
        panel.enter("55.55");
        QVERIFY2(panel.editor()->isVisible(), "the password is asked for");
        QCOMPARE(panel.editor()->echoMode(), QLineEdit::Password);
        panel.enter("guess");
        QVERIFY(panel.message().contains("Wrong password"));
        QCOMPARE(panel.value(30, 0, 0, 10), 0.0);
        panel.press(Qt::Key_Return);
        panel.editor()->clear();
        panel.enter("55.55");
        panel.enter(mtc::core::kDefaultMachineDataPassword);
        QCOMPARE(panel.value(30, 0, 0, 10), 55.6);
        QCOMPARE(panel.cell(9, 2), QString("55.6"));
        QVERIFY(panel.message().contains("= 55.6"));
        panel.down(3);  // 013 maximum feed reduction: no second prompt
        panel.press(Qt::Key_Return);
        panel.editor()->clear();
        panel.enter("70");
        QCOMPARE(panel.value(30, 0, 0, 13), 70.0);
        // Leaving the screen locks again.
        QVERIFY(panel.window->showScreen("signals"));
        QVERIFY(panel.open());
        panel.down(12);
        panel.press(Qt::Key_Return);
        panel.editor()->clear();
        panel.enter("60");
        QVERIFY(panel.editor()->isVisible());
        QCOMPARE(panel.editor()->echoMode(), QLineEdit::Password);
        panel.press(Qt::Key_Escape);
        QVERIFY(panel.editor()->isHidden());
        QCOMPARE(panel.window->currentScreenName(), QString("machine-data"));
        QCOMPARE(panel.value(30, 0, 0, 13), 70.0);
    }

    void invalidValuesKeepTheOldOne() {
        MachineDataPanel panel;
        QVERIFY(panel.open());
        panel.press(Qt::Key_Right);  // page 60: no password
        panel.down(4);               // 005 T no. tool spindle 1
        panel.press(Qt::Key_Return);
        panel.editor()->clear();
        panel.enter("12");
        QCOMPARE(panel.value(60, 0, 0, 5), 12.0);
        panel.press(Qt::Key_Return);
        panel.editor()->clear();
        panel.enter("twelve");
        QVERIFY(panel.message().contains("'twelve' is not a number"));
        QVERIFY(panel.message().contains("stays 12"));
        panel.press(Qt::Key_Return);
        panel.editor()->clear();
        panel.enter("10000000");
        QVERIFY(panel.message().contains("outside"));
        QVERIFY(panel.message().contains("0 .. 9999999"));
        panel.press(Qt::Key_Return);
        panel.editor()->clear();
        panel.enter("3.5");
        QVERIFY(panel.message().contains("whole numbers"));
        QCOMPARE(panel.value(60, 0, 0, 5), 12.0);
        QCOMPARE(panel.cell(4, 2), QString("12"));
    }

    void valuesFollowTheNc() {
        MachineDataPanel panel;
        QVERIFY(panel.open());
        QCOMPARE(panel.cell(6, 2), QString("0.0"));
        QCOMPARE(panel.session->machineData().update({30, 0, 0, 7}, 12.34), MachineDataStatus::Ok);
        panel.session->notifyChanged(0);
        QCOMPARE(panel.cell(6, 2), QString("12.3"));
    }

    void panelKeepsValuesInItsDataFile() {
        QTemporaryDir dir;
        mtc::hmi::PanelOptions options;
        options.dataFile = dir.filePath("cell.mdt");
        {
            MachineDataPanel panel(options);
            QVERIFY(panel.open());
            panel.press(Qt::Key_Right);
            panel.press(Qt::Key_Return);
            panel.editor()->clear();
            panel.enter("1");
            QCOMPARE(panel.value(60, 0, 0, 1), 1.0);
        }
        {
            MachineDataPanel panel(options);
            QCOMPARE(panel.value(60, 0, 0, 1), 1.0);
        }
        QFile file(options.dataFile);
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write("garbage");
        file.close();
        MachineDataPanel panel(options);
        QVERIFY(panel.open());
        QVERIFY(panel.message().contains("damaged"));
        QCOMPARE(panel.value(60, 0, 0, 1), 0.0);
        QCOMPARE(QDir(dir.path()).entryList({"cell.mdt.damaged-*"}).size(), 1);
    }

    // CF-021: another program (here: the core's file access, as `md set` does)
    // changes the data file under the panel; the panel takes the value over
    // and says so, and its own next save does not write the old value back.
    void anotherProgramsChangeIsTakenOver() {
        QTemporaryDir dir;
        mtc::hmi::PanelOptions options;
        options.dataFile = dir.filePath("cell.mdt");
        MachineDataPanel panel(options);
        QVERIFY(panel.open());
        panel.press(Qt::Key_Right);  // page 60
        panel.press(Qt::Key_Return);
        panel.editor()->clear();
        panel.enter("1");  // element 1, saved
        QCOMPARE(panel.value(60, 0, 0, 1), 1.0);
        {
            mtc::core::MachineDataStore other(panel.session->config());
            mtc::core::SharedMachineDataFile file(options.dataFile.toStdString());
            file.open(other, true);
            other.update({60, 0, 0, 5}, 4711);
            QVERIFY(file.save(other).ok);
        }
        QTRY_COMPARE(panel.value(60, 0, 0, 5), 4711.0);  // within the 1 s check
        QTRY_VERIFY2(panel.message().contains("taken over"), qPrintable(panel.message()));
        QTRY_COMPARE(panel.cell(4, 2), QString("4711"));
        panel.down(1);  // element 2: the panel saves again
        panel.press(Qt::Key_Return);
        panel.editor()->clear();
        panel.enter("1");
        mtc::core::MachineDataStore check(panel.session->config());
        mtc::core::SharedMachineDataFile file(options.dataFile.toStdString());
        file.open(check);
        double value = 0;
        check.read({60, 0, 0, 5}, value);
        QCOMPARE(value, 4711.0);
        check.read({60, 0, 0, 2}, value);
        QCOMPARE(value, 1.0);
    }
};

QTEST_MAIN(MachineDataScreenTest)
#include "test_machine_data_screen.moc"
