// Tool table and zero offset screens by keys, on both stations: a tool
// radius and a zero offset typed into the table change the next run's
// path and are in the files beside the machine data at once; a refused
// entry keeps the old value and says why; tools and edges are added and
// removed by soft keys.
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QTableView>
#include <QTemporaryDir>

#include "PanelFixture.h"
#include "cnc_core/cell/Station.h"
#include "cnc_core/tooldata/SetupDataEditor.h"

namespace {

// Mill: T1 (radius 3.5) runs left of the contour along +X: the tool centre
// ends at Y = programmed + R. G54 X-150 Y-80 Z-120.
const char* kMillProgram =
    "N0001 T1 G17 G90 G54 G0 X0 Y20 Z2\nN0002 G1 G41 Y0 F3000\nN0003 X30\nN0004 M30\n";
// Lathe: T1 (radius 0.4, edge position 3) right of the contour along -Z.
// G54 X0 Z255.5.
const char* kLatheProgram =
    "N0001 T1 G18 G90 G54 G0 X40 Z10\nN0002 G1 G42 X30 F600\nN0003 Z-20\nN0004 M30\n";

struct ToolPanel : PanelFixture {
    explicit ToolPanel(const mtc::hmi::PanelOptions& options) : PanelFixture(options) {
        session->setTimerEnabled(false);
    }

    mtc::hmi::Screen* open(int station, const char* name) {
        window->showStation(station);
        if (!window->showScreen(name)) return nullptr;
        return window->screen(station, name);
    }
    static QAbstractItemModel* table(mtc::hmi::Screen* screen, const char* name) {
        return screen->findChild<QTableView*>(name)->model();
    }
    static QString text(mtc::hmi::Screen* screen, const char* name) {
        return screen->findChild<QLabel*>(name)->text();
    }
    /// Types `value` over the selected text of the open input, then Enter.
    void enter(const QString& value) {
        QTest::keyClicks(QApplication::focusWidget(), value);
        press(Qt::Key_Return);
    }
    /// Runs `program` on `station` to its end by the Start key; the
    /// compensated position of every axis at the end.
    std::vector<double> run(int station, int number, const char* program) {
        session->addProgram(station, number, "test.nc", program);
        if (!session->selectProgram(station, number)) return {};
        window->showStation(station);
        press(Qt::Key_F5, Qt::ShiftModifier);  // Start
        for (int tick = 0; tick < 5000 && session->control(station).programActive(); ++tick)
            session->advance(0.02);
        std::vector<double> end;
        for (int axis = 0; axis < 3; ++axis)
            end.push_back(session->station(station).machine().position(axis));
        return end;
    }
    static QString file(const QString& path) {
        QFile f(path);
        return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
    }
    /// Presses Right until the cursor is in the column headed `header`.
    void toColumn(QAbstractItemModel* model, const QString& header) {
        for (int c = 0; c < model->columnCount(); ++c)
            if (model->headerData(c, Qt::Horizontal).toString() == header) {
                press(Qt::Key_Home);
                for (int i = 0; i < c; ++i)
                    press(Qt::Key_Right);
                return;
            }
        QFAIL(qPrintable("no column " + header));
    }
};

mtc::hmi::PanelOptions withDataIn(const QTemporaryDir& dir) {
    mtc::hmi::PanelOptions options;
    options.dataFile = dir.filePath("cell.mdt");
    return options;
}

}  // namespace

class ToolScreensTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { useTestSettings(); }

    void millRadiusByKeysChangesTheNextRunAndIsSaved() {
        QTemporaryDir dir;
        ToolPanel panel(withDataIn(dir));
        const std::vector<double> before = panel.run(0, 60, kMillProgram);
        QCOMPARE(before.at(1), -80.0 + 3.5);
        mtc::hmi::Screen* screen = panel.open(0, "tools");
        QVERIFY(screen);
        QAbstractItemModel* table = ToolPanel::table(screen, "toolTable");
        QCOMPARE(table->headerData(3, Qt::Horizontal).toString(), QString("R"));
        QCOMPARE(table->index(0, 0).data().toString(), QString("\u2192T1"));
        QCOMPARE(table->index(0, 3).data().toString(), QString("3.500"));
        panel.press(Qt::Key_Return);  // the cursor starts on R of T1 E1
        auto* editor = screen->findChild<QLineEdit*>("toolEditor");
        QVERIFY(editor->isVisible());
        QCOMPARE(editor->text(), QString("3.5"));
        QVERIFY(ToolPanel::text(screen, "toolPrompt").contains("0 .. 999.99999 mm"));
        panel.enter("4.25");
        QCOMPARE(table->index(0, 3).data().toString(), QString("4.250"));
        QVERIFY2(ToolPanel::text(screen, "toolMessage").contains("T1 E1 radius R = 4.25"),
                 qPrintable(ToolPanel::text(screen, "toolMessage")));
        QVERIFY(ToolPanel::file(dir.filePath("cell.tools")).contains("T1 E1 radius=4.25 "));

        const std::vector<double> after = panel.run(0, 61, kMillProgram);
        QCOMPARE(after.at(1), -80.0 + 4.25);
        QCOMPARE(after.at(0), before.at(0));
    }

    void aRefusedEntryKeepsTheOldValueAndSaysWhy() {
        QTemporaryDir dir;
        ToolPanel panel(withDataIn(dir));
        mtc::hmi::Screen* screen = panel.open(0, "tools");
        QAbstractItemModel* table = ToolPanel::table(screen, "toolTable");
        panel.press(Qt::Key_Return);
        panel.enter("-1");
        QString message = ToolPanel::text(screen, "toolMessage");
        QVERIFY2(message.contains("out of range (allowed 0 .. 999.99999 mm)"), qPrintable(message));
        QVERIFY(message.contains("T1 E1 radius R stays 3.5"));
        QCOMPARE(table->index(0, 3).data().toString(), QString("3.500"));
        QVERIFY(!QFile::exists(dir.filePath("cell.tools")));
        panel.press(Qt::Key_Right);  // R wear
        panel.press(Qt::Key_Return);
        panel.enter("0,1");
        QVERIFY(ToolPanel::text(screen, "toolMessage").contains("not a decimal number"));
        panel.press(Qt::Key_End);  // setting angle
        panel.press(Qt::Key_Return);
        panel.enter("400");
        QVERIFY(ToolPanel::text(screen, "toolMessage").contains("allowed 0 .. 360 degrees"));
        panel.press(Qt::Key_Home);  // T: not edited
        panel.press(Qt::Key_Return);
        QVERIFY(screen->findChild<QLineEdit*>("toolEditor")->isHidden());
        QVERIFY(ToolPanel::text(screen, "toolMessage").contains("not edited"));
        QCOMPARE(panel.session->setupData().tools(0)->edge(1, 1)->radiusWear, 0.0);
        // Escape leaves the value too.
        panel.press(Qt::Key_Right);  // name
        panel.press(Qt::Key_Return);
        panel.press(Qt::Key_Escape);
        QVERIFY(ToolPanel::text(screen, "toolMessage").contains("stays mill1"));
        QCOMPARE(panel.window->currentScreenName(), QString("tools"));
    }

    void toolsAndEdgesAreAddedAndRemovedBySoftKeys() {
        QTemporaryDir dir;
        ToolPanel panel(withDataIn(dir));
        mtc::hmi::Screen* screen = panel.open(0, "tools");
        QAbstractItemModel* table = ToolPanel::table(screen, "toolTable");
        const int rows = table->rowCount();
        panel.press(Qt::Key_F2);  // New tool
        panel.enter("1");
        QVERIFY(ToolPanel::text(screen, "toolMessage").contains("T1 is already in the tool list"));
        panel.press(Qt::Key_F2);
        panel.enter("77");
        QCOMPARE(table->rowCount(), rows + 1);
        QVERIFY(ToolPanel::text(screen, "toolMessage").contains("New tool T77 E1"));
        panel.press(Qt::Key_Return);  // the cursor is on the new tool's R
        panel.enter("2.5");
        panel.press(Qt::Key_F3);  // New edge
        panel.enter("2");
        QCOMPARE(table->rowCount(), rows + 2);
        QVERIFY(ToolPanel::text(screen, "toolMessage").contains("T77 E2"));
        const QString tools = ToolPanel::file(dir.filePath("cell.tools"));
        QVERIFY(tools.contains("T77 E1 radius=2.5 "));
        QVERIFY(tools.contains("T77 E2 radius=0 "));
        panel.press(Qt::Key_F4);  // Delete edge: asks first
        panel.press(Qt::Key_Escape);
        QCOMPARE(table->rowCount(), rows + 2);
        panel.press(Qt::Key_F4);
        panel.press(Qt::Key_Return);
        QCOMPARE(table->rowCount(), rows + 1);
        QVERIFY(!ToolPanel::file(dir.filePath("cell.tools")).contains("T77 E2"));
        panel.press(Qt::Key_F5);  // Delete tool
        QVERIFY(ToolPanel::text(screen, "toolPrompt").contains("T77"));
        panel.press(Qt::Key_Return);
        QCOMPARE(table->rowCount(), rows);
        QVERIFY(panel.session->setupData().tools(0)->find(77) == nullptr);
        QVERIFY(!ToolPanel::file(dir.filePath("cell.tools")).contains("T77"));
    }

    void millZeroOffsetByKeysMovesTheNextRun() {
        QTemporaryDir dir;
        ToolPanel panel(withDataIn(dir));
        const std::vector<double> before = panel.run(0, 60, kMillProgram);
        QCOMPARE(before.at(0), -150.0 + 30.0);
        mtc::hmi::Screen* screen = panel.open(0, "offsets");
        QAbstractItemModel* table = ToolPanel::table(screen, "offsetTable");
        QCOMPARE(table->index(0, 0).data().toString(), QString("\u2192G54"));
        QCOMPARE(table->headerData(1, Qt::Horizontal).toString(), QString("X"));
        QCOMPARE(table->index(0, 1).data().toString(), QString("-150.000"));
        panel.press(Qt::Key_Return);  // G54 X
        panel.enter("-140.5");
        QCOMPARE(table->index(0, 1).data().toString(), QString("-140.500"));
        QVERIFY(ToolPanel::file(dir.filePath("cell.offsets")).contains("G54 X=-140.5 Y=-80"));
        panel.press(Qt::Key_Return);
        panel.enter("100000");
        const QString message = ToolPanel::text(screen, "offsetMessage");
        QVERIFY2(message.contains("out of range (allowed -99999.9999 .. 99999.9999"),
                 qPrintable(message));
        QVERIFY(message.contains("G54 X stays -140.5"));
        const std::vector<double> after = panel.run(0, 61, kMillProgram);
        QCOMPARE(after.at(0), -140.5 + 30.0);
        QCOMPARE(after.at(1), before.at(1));
    }

    void latheRadiusAndZeroOffsetByKeys() {
        QTemporaryDir dir;
        ToolPanel panel(withDataIn(dir));
        const std::vector<double> before = panel.run(1, 60, kLatheProgram);
        mtc::hmi::Screen* tools = panel.open(1, "tools");
        QVERIFY(ToolPanel::text(tools, "toolHeading").contains("process 1"));
        QAbstractItemModel* toolTable = ToolPanel::table(tools, "toolTable");
        QCOMPARE(toolTable->index(0, 3).data().toString(), QString("0.400"));
        QCOMPARE(toolTable->index(0, 11).data().toString(), QString("3"));
        panel.press(Qt::Key_Return);
        panel.enter("1.4");
        QVERIFY(ToolPanel::file(dir.filePath("cell.tools")).contains("T1 E1 radius=1.4 "));
        QCOMPARE(panel.session->setupData().tools(0)->edge(1, 1)->radius, 3.5);
        const std::vector<double> wider = panel.run(1, 61, kLatheProgram);
        // One more mm of radius puts the tool nose centre one more mm away
        // from the contour: the end point moves by 1 mm in all.
        double moved = 0.0;
        for (std::size_t axis = 0; axis < before.size(); ++axis)
            moved += std::abs(wider.at(axis) - before.at(axis));
        QVERIFY2(std::abs(moved - 1.0) < 1e-9, qPrintable(QString::number(moved)));

        mtc::hmi::Screen* offsets = panel.open(1, "offsets");
        QAbstractItemModel* offsetTable = ToolPanel::table(offsets, "offsetTable");
        panel.toColumn(offsetTable, "Z");
        panel.press(Qt::Key_Return);
        QCOMPARE(offsets->findChild<QLineEdit*>("offsetEditor")->text(), QString("255.5"));
        panel.enter("250");
        QVERIFY(ToolPanel::file(dir.filePath("cell.offsets")).contains("G54 Z=250"));
        panel.press(Qt::Key_Return);
        panel.enter("zero");
        QVERIFY(ToolPanel::text(offsets, "offsetMessage").contains("not a decimal number"));
        QVERIFY(ToolPanel::text(offsets, "offsetMessage").contains("G54 Z stays 250"));
        const std::vector<double> shifted = panel.run(1, 62, kLatheProgram);
        double dz = 0.0;
        for (std::size_t axis = 0; axis < wider.size(); ++axis)
            dz += wider.at(axis) - shifted.at(axis);
        QCOMPARE(dz, 5.5);
    }

    // Another program (`offsets set`, here the core's editor as the CLI uses
    // it) saves the file under the panel: within the 1 s check the table
    // shows the new value and says so.
    void anotherProgramsSaveIsShown() {
        QTemporaryDir dir;
        ToolPanel panel(withDataIn(dir));
        mtc::hmi::Screen* screen = panel.open(0, "offsets");
        QAbstractItemModel* table = ToolPanel::table(screen, "offsetTable");
        QCOMPARE(table->index(1, 1).data().toString(), QString("50.000"));
        {
            mtc::core::DiagnosticList problems;
            mtc::core::SetupData other =
                mtc::core::SetupData::fromConfig(panel.session->config(), problems);
            mtc::core::SetupDataEditor cli(
                other, mtc::core::setupDataFilesBeside(dir.filePath("cell.mdt").toStdString()));
            QVERIFY(cli.setOffsets(0, 55, {{"X", "61.25"}}).saved);
        }
        QTRY_COMPARE(table->index(1, 1).data().toString(), QString("61.250"));
        QVERIFY(ToolPanel::text(screen, "offsetMessage").contains("taken over"));
        QCOMPARE(panel.session->setupData().offsets(0)->value(55, mtc::core::AxisDefinition::X),
                 61.25);
    }

    void theScreensAreInTheMainMenu() {
        QTemporaryDir dir;
        ToolPanel panel(withDataIn(dir));
        QVERIFY(panel.registry.find("tools") && panel.registry.find("tools")->inMainMenu);
        QVERIFY(panel.registry.find("offsets") && panel.registry.find("offsets")->inMainMenu);
        mtc::hmi::Screen* screen = panel.open(0, "offsets");
        QVERIFY(ToolPanel::text(screen, "offsetHeading").contains(dir.filePath("cell.offsets")));
        panel.press(Qt::Key_F8);  // Back
        QCOMPARE(panel.window->currentScreenName(), QString("menu"));
    }
};

QTEST_MAIN(ToolScreensTest)
#include "test_tool_screens.moc"
