// Main menu: every registered screen reachable by cursor + Enter and by soft key.
#include <QListWidget>

#include "PanelFixture.h"
#include "hmi/SoftKeyBar.h"

class MenuScreenTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { useTestSettings(); }

    void listsEveryScreenButItself() {
        PanelFixture panel;
        auto* list = panel.window->screen(0, "menu")->findChild<QListWidget*>("menuList");
        QVERIFY(list);
        int offered = 0;  // screens registered for the main menu
        for (const auto& entry : panel.registry.entries())
            offered += entry.inMainMenu ? 1 : 0;
        QCOMPARE(list->count(), offered - 1);
        for (int row = 0; row < list->count(); ++row)
            QVERIFY(!list->item(row)->text().contains("(menu)"));
    }

    void cursorAndEnterOpenTheScreen() {
        PanelFixture panel;
        auto* list = panel.window->screen(0, "menu")->findChild<QListWidget*>("menuList");
        QCOMPARE(QApplication::focusWidget(), list);
        panel.press(Qt::Key_Down);
        QCOMPARE(list->currentRow(), 1);
        const QString expected = list->currentItem()->text().section('(', 1).chopped(1);
        panel.press(Qt::Key_Return);
        QCOMPARE(panel.window->currentScreenName(), expected);
    }

    void softKeysCarryTheScreenTitles() {
        PanelFixture panel;
        auto* bar = panel.window->softKeyBar();
        int row = 0;
        for (const auto& entry : panel.registry.entries()) {
            if (entry.name == "menu" || !entry.inMainMenu) continue;
            if (row >= 7) break;
            QCOMPARE(bar->label(row++), entry.title);
        }
    }
};

QTEST_MAIN(MenuScreenTest)
#include "test_menu_screen.moc"
