// Soft key labels are never clipped (issue 20 §3): each label is broken into
// lines at blanks to fit its button; what still cannot fit is shortened with
// "…" and the whole label is the button's tooltip.
#include <QFontMetrics>
#include <QPushButton>

#include "PanelFixture.h"
#include "hmi/SoftKeyBar.h"
#include "hmi/SoftKeyButton.h"

namespace {

/// Every line of the button's text fits its width (the frame's share left out).
bool everyLineFits(const QPushButton* button) {
    const QFontMetrics metrics(button->font());
    for (const QString& line : button->text().split('\n'))
        if (metrics.horizontalAdvance(line) > button->width() - 10) return false;
    return true;
}

/// The label lines of the button joined with blanks (the key name left out).
QString shownLabel(const QPushButton* button) {
    QStringList lines = button->text().split('\n');
    lines.removeFirst();
    return lines.join(' ');
}

}  // namespace

class SoftKeyLabelsTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { useTestSettings(); }

    void mainMenuLabelsAreShownWholeAtTheDefaultSize() {
        PanelFixture panel;
        QCOMPARE(panel.window->currentScreenName(), QString("menu"));
        for (int key = 1; key <= 8; ++key) {
            auto* button = panel.window->findChild<mtc::hmi::SoftKeyButton*>(
                QString("softkey%1").arg(key));
            QVERIFY(button);
            QVERIFY2(everyLineFits(button), qPrintable(button->text()));
            QVERIFY2(!button->shortened(), qPrintable(button->label()));
            QCOMPARE(shownLabel(button), QString(button->label()).replace('\n', ' '));
            QVERIFY(button->toolTip().isEmpty());
        }
        // The key that was clipped before: "MDI (manual data input)".
        auto* f4 = panel.window->findChild<mtc::hmi::SoftKeyButton*>("softkey4");
        QVERIFY(f4->text().startsWith("F4\n"));
        QVERIFY(f4->label().contains("manual data input"));
    }

    void aNarrowBarShortensWithTheWholeLabelAsTooltip() {
        mtc::hmi::SoftKeyBar bar;
        bar.setKeys({{"Adaptive feed trend with a very long explanation", [] {}, true},
                     {"Back", [] {}, true}});
        bar.resize(480, 100);
        bar.show();
        QVERIFY(QTest::qWaitForWindowExposed(&bar));
        auto* first = bar.findChild<mtc::hmi::SoftKeyButton*>("softkey1");
        auto* second = bar.findChild<mtc::hmi::SoftKeyButton*>("softkey2");
        QVERIFY(first->shortened());
        QVERIFY(everyLineFits(first));
        QVERIFY(first->text().contains(QChar(0x2026)));  // "…"
        QCOMPARE(first->toolTip(), QString("Adaptive feed trend with a very long explanation"));
        QVERIFY(!second->shortened());
        QCOMPARE(second->text(), QString("F2\nBack"));
        QVERIFY(second->toolTip().isEmpty());
        // Wider again: the whole label, no tooltip.
        bar.resize(2400, 100);
        QTRY_VERIFY(!first->shortened());
        QVERIFY(first->toolTip().isEmpty());
    }

    void fitLinesBreaksAtBlanksAndKeepsForcedBreaks() {
        const QFontMetrics metrics(QApplication::font());
        bool shortened = true;
        const int wide = metrics.horizontalAdvance("Compiler active: No") + 2;
        QCOMPARE(mtc::hmi::SoftKeyButton::fitLines("Compiler active: No", metrics, wide, 3,
                                                    shortened),
                 QStringList{"Compiler active: No"});
        QVERIFY(!shortened);
        const int narrow = metrics.horizontalAdvance("Compiler") + 2;
        QCOMPARE(mtc::hmi::SoftKeyButton::fitLines("Compiler active: No", metrics, narrow, 3,
                                                    shortened),
                 (QStringList{"Compiler", "active:", "No"}));
        QVERIFY(!shortened);
        QCOMPARE(mtc::hmi::SoftKeyButton::fitLines("Select\nprogram", metrics, wide, 3, shortened),
                 (QStringList{"Select", "program"}));
        const QStringList four = mtc::hmi::SoftKeyButton::fitLines("a b c d", metrics,
                                                                   metrics.horizontalAdvance("a b"),
                                                                   1, shortened);
        QCOMPARE(four.size(), 1);
        QVERIFY(shortened);
    }
};

QTEST_MAIN(SoftKeyLabelsTest)
#include "test_softkey_labels.moc"
