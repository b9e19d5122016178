// The panel on a German desk (issue 20 §2, D-013): run with
// LC_ALL=de_DE.UTF-8 (tests/CMakeLists.txt), QApplication takes the desk's
// locale; a decimal value typed with the real keys on the machine data
// screen is stored exactly, shown with '.', written with '.' to the data
// file and read back by the next panel.
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QTableView>
#include <QTemporaryDir>
#include <clocale>
#include <cstdio>

#include "PanelFixture.h"
#include "cnc_core/machine_data/MachineDataStore.h"

namespace {

struct GermanDeskPanel : PanelFixture {
    using PanelFixture::PanelFixture;

    QString cell(mtc::hmi::Screen* screen, int row, int column) const {
        return screen->findChild<QTableView*>("mdTable")
            ->model()
            ->index(row, column)
            .data()
            .toString();
    }
    double value(int page, int process, int sub, int element) const {
        double v = -1;
        session->machineData().read({page, process, sub, element}, v);
        return v;
    }
};

}  // namespace

class LocaleNumbersTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() {
        useTestSettings();
        const char* type = std::setlocale(LC_CTYPE, nullptr);
        if (!QByteArray(type).startsWith("de_DE"))
            QSKIP("runs under LC_ALL=de_DE.UTF-8 (the locale is installed by scripts/setup.sh)");
    }

    void decimalValueTypedOnTheMachineDataScreen() {
        QTemporaryDir dir;
        mtc::hmi::PanelOptions options;
        options.dataFile = dir.filePath("cell.mdt");
        {
            GermanDeskPanel panel(options);
            QCOMPARE(QByteArray(std::setlocale(LC_NUMERIC, nullptr)), QByteArray("C"));
            QVERIFY2(QByteArray(std::setlocale(LC_CTYPE, nullptr)).startsWith("de_DE"),
                     "only the number format goes back to C; the rest stays the desk's");
            char text[16];
            std::snprintf(text, sizeof text, "%.2f", 612.25);
            QCOMPARE(QByteArray(text), QByteArray("612.25"));

            panel.window->showStation(1);
            QVERIFY(panel.window->showScreen("machine-data"));
            mtc::hmi::Screen* screen = panel.window->screen(1, "machine-data");
            QVERIFY(screen);
            panel.press(Qt::Key_Left);  // page 180 of the lathe
            QVERIFY(screen->findChild<QLabel*>("mdPage")->text().contains("Page 180"));
            panel.press(Qt::Key_Down);
            panel.press(Qt::Key_Return);
            QTest::keyClicks(QApplication::focusWidget(), "612.25");
            panel.press(Qt::Key_Return);
            QCOMPARE(panel.value(180, 1, 0, 2), 612.25);
            QCOMPARE(panel.cell(screen, 1, 2), QString("612.25"));

            panel.press(Qt::Key_Up);  // a decimal comma is no number: old value kept
            panel.press(Qt::Key_Return);
            QTest::keyClicks(QApplication::focusWidget(), "7,5");
            panel.press(Qt::Key_Return);
            QCOMPARE(panel.value(180, 1, 0, 1), 0.0);
            QVERIFY(!screen->findChild<QLabel*>("mdMessage")->text().isEmpty());
        }
        QFile file(options.dataFile);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray text = file.readAll();
        QVERIFY2(text.contains("\n1 180 0 2 612.25\n"), text.constData());
        GermanDeskPanel again(options);
        QCOMPARE(again.value(180, 1, 0, 2), 612.25);
    }

    // The German desk gets the German panel (D-018) and its numbers stay
    // C-locale text: '.' and no thousands separator on the base screen.
    void germanPanelShowsNumbersWithAPoint() {
        mtc::hmi::PanelOptions options;
        options.language = mtc::hmi::panelLanguageFor("");
        QCOMPARE(options.language, QString("de"));
        GermanDeskPanel panel(options);
        panel.window->showStation(1);
        QVERIFY(panel.window->showScreen("position"));
        mtc::hmi::Screen* screen = panel.window->screen(1, "position");
        QCOMPARE(screen->title(), QString("Grundbild (Position)"));
        auto* header = panel.window->findChild<QLabel*>("headerMode");
        QVERIFY2(header->text().startsWith("Betriebsart: "), qPrintable(header->text()));
        panel.session->station(1).control().press(mtc::core::ControlKey::Manual);
        panel.session->station(1).jogBy(0, 12.5, false);
        panel.session->station(1).advance(3600.0);
        panel.session->notifyChanged(1);
        const QString shown = screen->findChild<QLabel*>("axisMachine-0")->text();
        QVERIFY2(shown.startsWith("+12.500"), qPrintable(shown));
        const QString feeds = screen->findChild<QLabel*>("feedValues")->text();
        QVERIFY2(feeds.startsWith("F programmiert") && feeds.contains("0.0 mm/min"),
                 qPrintable(feeds));
    }
};

QTEST_MAIN(LocaleNumbersTest)
#include "hmi/PanelLanguage.h"
#include "test_locale_numbers.moc"
