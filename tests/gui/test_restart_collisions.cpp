// The restart's way back against the part on the result review (issue 19
// §4, D-021), by keys: Shift+F1, the cursor on the target, Enter; when the
// computing process reaches the target the review lists in red every ADJUST /
// REPOS move that would cut the part (block, phase, position) before Start,
// and says so when the way back is clear.
#include <QHeaderView>
#include <QLabel>
#include <QStyle>
#include <QTableView>
#include <QTextLayout>

#include "PanelFixture.h"
#include "hmi/ColumnFit.h"
#include "screens/restart/RestartController.h"
#include "screens/restart/RestartResultModel.h"
#include "screens/restart/RestartRun.h"
#include "screens/restart/RestartScreen.h"
#include "tests/support/SlotRestartProgram.h"

namespace {

using mtc::screens::RestartResultModel;

// The slot of tests/support/SlotRestartProgram.h (mill, T2, target N0050).
const char* kSlot = mtc::test::kSlotRestartProgram;

// ADJUST leaves the tool beside the part below its top; REPOS goes straight.
const char* kStraightBack =
    "N0000 M30\n"
    "N0001 .ADJUST G0 G54 X120 Y30 Z-2\n"
    "N0002 .REPOS G77 X0 Y0 F2000\n"
    "N0003 G77 Z0 F500 RTS\n";

// The same with the tool above the part first.
const char* kOverTheTop =
    "N0000 M30\n"
    "N0001 .ADJUST G0 G54 Z20\n"
    "N0002 .REPOS G77 X0 Y0 F2000\n"
    "N0003 G77 Z0 F500 RTS\n";

/// Selects program 40, opens the restart screen (Shift+F1), moves the
/// cursor to N0050 and accepts it with Enter, as an operator does.
void restartAtTheTarget(PanelFixture& panel) {
    panel.session->selectProgram(0, 40);
    panel.press(Qt::Key_F1, Qt::ShiftModifier);
    for (int i = 0; i < 4; ++i)
        panel.press(Qt::Key_Down);  // N0010 .. N0050
    panel.press(Qt::Key_Return);
}

mtc::screens::RestartRun* run(PanelFixture& panel) {
    return static_cast<mtc::screens::RestartScreen*>(panel.window->screen(0, "restart"))
        ->controller()
        ->run();
}

/// The rows the review marks as collisions: {item, what}.
QList<QStringList> collisionRows(QAbstractItemModel* model) {
    QList<QStringList> rows;
    for (int row = 0; row < model->rowCount(); ++row)
        if (model->index(row, 0).data(RestartResultModel::CollisionRole).toBool())
            rows << QStringList{model->index(row, 0).data().toString(),
                                model->index(row, 1).data().toString()};
    return rows;
}

/// The size of `text` in `font` wrapped at `width` as the style paints a
/// cell's text (QTextLayout, word wrap): the widest line, the lines' height.
QSizeF wrapped(const QString& text, const QFont& font, int width) {
    QTextLayout layout(text, font);
    QTextOption option;
    option.setWrapMode(QTextOption::WordWrap);
    layout.setTextOption(option);
    layout.beginLayout();
    QSizeF size(0, 0);
    for (QTextLine line = layout.createLine(); line.isValid(); line = layout.createLine()) {
        line.setLineWidth(width);
        size.setWidth(std::max(size.width(), line.naturalTextWidth()));
        size.setHeight(size.height() + line.height());
    }
    layout.endLayout();
    return size;
}

/// The first cell or title of `table` whose text is cut, described; "" when
/// every text is shown whole: each cell's text, wrapped at blanks in its
/// room (the width of its columns, a heading spans several, less the
/// delegate's margins and the grid line), is no wider than that room and no
/// higher than its row; each title fits its section on one line (the
/// header's own size hint).
QString firstCutText(const QTableView* table) {
    const QAbstractItemModel* model = table->model();
    const int margin =
        2 * (table->style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, table) + 1) + 1;
    for (int column = 0; column < model->columnCount(); ++column) {
        const int titleWidth = table->horizontalHeader()->sectionSizeHint(column);
        if (titleWidth > table->columnWidth(column))
            return QString("title '%1' needs %2 px, has %3")
                .arg(model->headerData(column, Qt::Horizontal).toString())
                .arg(titleWidth)
                .arg(table->columnWidth(column));
    }
    for (int row = 0; row < model->rowCount(); ++row) {
        int span = 1;
        for (int column = 0; column < model->columnCount(); column += span) {
            span = std::max(1, table->columnSpan(row, column));
            int room = -margin;
            for (int c = column; c < column + span; ++c)
                room += table->columnWidth(c);
            const QModelIndex index = model->index(row, column);
            const QString text = index.data().toString();
            const QVariant font = index.data(Qt::FontRole);
            const QSizeF needed = wrapped(
                text, font.isValid() ? font.value<QFont>().resolve(table->font()) : table->font(),
                room);
            if (needed.width() > room || needed.height() > table->rowHeight(row) - 1)
                return QString("row %1 column %2 '%3' needs %4x%5 px, has %6x%7")
                    .arg(row)
                    .arg(column)
                    .arg(text)
                    .arg(needed.width())
                    .arg(needed.height())
                    .arg(room)
                    .arg(table->rowHeight(row));
        }
    }
    return {};
}

}  // namespace

class RestartCollisionsTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { useTestSettings(); }

    void aWayBackThroughThePartIsListedInRedBeforeStart() {
        PanelFixture panel;
        panel.session->addProgram(0, 99, "N1010099.DAT", kStraightBack);
        panel.session->addProgram(0, 40, "slot.nc", kSlot);
        restartAtTheTarget(panel);
        QTRY_COMPARE(run(panel)->phase(), mtc::core::RestartPhase::TargetReached);
        QCOMPARE(panel.window->currentScreenName(), QString("restart-result"));
        QWidget* review = panel.window->screen(0, "restart-result");
        auto* table = review->findChild<QTableView*>("resultTable");
        const QList<QStringList> rows = collisionRows(table->model());
        QCOMPARE(rows.size(), 1);
        QVERIFY2(rows[0][0].startsWith("REPOS P99 N0002 (line 3): feed move cuts the part"),
                 qPrintable(rows[0][0]));
        // It enters the part's X100 face with the cutter's centre at X104.9.
        QVERIFY2(rows[0][1].startsWith("X-45.1"), qPrintable(rows[0][1]));
        QVERIFY2(rows[0][1].endsWith("Y-50.000 Z-122.000 (machine)"), qPrintable(rows[0][1]));
        // Red, listed first (before the G functions), not counted as a difference.
        const QModelIndex first = table->model()->index(1, 0);
        QVERIFY(first.data(RestartResultModel::CollisionRole).toBool());
        QCOMPARE(first.data(Qt::ForegroundRole).value<QBrush>().color(), QColor(0xb0, 0x00, 0x00));
        QVERIFY(!first.data(RestartResultModel::DiffersRole).toBool());
        auto* banner = review->findChild<QLabel*>("resultCollisions");
        QVERIFY(banner->isVisible());
        QVERIFY2(banner->text().startsWith("ADJUST/REPOS moves that collide with the part: 1 of 3"),
                 qPrintable(banner->text()));
        QVERIFY(banner->styleSheet().contains("#c00000"));
        // Differences only (F3) keeps the collision in view.
        panel.press(Qt::Key_F3);
        QCOMPARE(collisionRows(table->model()).size(), 1);
        // Nothing was started: the machine has not moved.
        QCOMPARE(run(panel)->phase(), mtc::core::RestartPhase::TargetReached);
        QCOMPARE(run(panel)->actualPosition(2), 0.0);
    }

    void aWayBackOverTheTopIsClearAndF4ChecksAgain() {
        PanelFixture panel;
        panel.session->addProgram(0, 99, "N1010099.DAT", kOverTheTop);
        panel.session->addProgram(0, 40, "slot.nc", kSlot);
        restartAtTheTarget(panel);
        QTRY_COMPARE(run(panel)->phase(), mtc::core::RestartPhase::TargetReached);
        QWidget* review = panel.window->screen(0, "restart-result");
        auto* table = review->findChild<QTableView*>("resultTable");
        QVERIFY(collisionRows(table->model()).isEmpty());
        auto* banner = review->findChild<QLabel*>("resultCollisions");
        QVERIFY2(banner->text() == "Way back clear: ADJUST/REPOS moves checked against the part: 3",
                 qPrintable(banner->text()));
        QVERIFY(!banner->styleSheet().contains("#c00000"));
        // The library changes (the commissioning engineer edits REPOS): F4
        // verifies the target again and checks the new way back.
        panel.session->addProgram(0, 99, "N1010099.DAT", kStraightBack);
        panel.press(Qt::Key_F4);
        QCOMPARE(collisionRows(table->model()).size(), 1);
        QVERIFY(banner->styleSheet().contains("#c00000"));
    }

    void columnsGetTheirLongestWordsThenTheShortestLinesWhole() {
        using mtc::hmi::fitColumnWidths;
        // {longest word, longest line}: a description, a short value, a long value.
        const std::vector<mtc::hmi::ColumnNeed> needs = {{100, 300}, {50, 50}, {80, 200}};
        // Room for every line: the rest to the last column.
        QCOMPARE(fitColumnWidths(needs, 1000), (std::vector<int>{300, 50, 650}));
        // 270 px beyond the words: the long value needs less than half of
        // it and gets its line, the description the rest.
        QCOMPARE(fitColumnWidths(needs, 500), (std::vector<int>{250, 50, 200}));
        // 170 px: each of the two long columns lacks more than its half.
        QCOMPARE(fitColumnWidths(needs, 400), (std::vector<int>{185, 50, 165}));
        // Not even the words fit: the words (the table scrolls sideways).
        QCOMPARE(fitColumnWidths(needs, 200), (std::vector<int>{100, 50, 80}));
    }

    void everyTextOfTheReviewIsShownWholeAtLargerFonts_data() {
        QTest::addColumn<double>("scale");
        // The application font at 96, 144 and 192 dpi without Qt's scaling
        // (text 1.5 and 2 times as many pixels in a window of the same
        // pixels): the case that cut the position column.
        QTest::newRow("96 dpi") << 1.0;
        QTest::newRow("144 dpi") << 1.5;
        QTest::newRow("192 dpi") << 2.0;
    }

    void everyTextOfTheReviewIsShownWholeAtLargerFonts() {
        QFETCH(double, scale);
        const QFont original = QApplication::font();
        QFont larger = original;
        larger.setPointSizeF(original.pointSizeF() * scale);
        QApplication::setFont(larger);
        {
            PanelFixture panel;
            panel.session->addProgram(0, 99, "N1010099.DAT", kStraightBack);
            panel.session->addProgram(0, 40, "slot.nc", kSlot);
            restartAtTheTarget(panel);
            QTRY_COMPARE(run(panel)->phase(), mtc::core::RestartPhase::TargetReached);
            auto* table =
                panel.window->screen(0, "restart-result")->findChild<QTableView*>("resultTable");
            QCOMPARE(collisionRows(table->model()).size(), 1);
            // The headings run across the table.
            QCOMPARE(table->model()->index(0, 0).data().toString(),
                     QString("Way back against the part (ADJUST / REPOS)"));
            QCOMPARE(table->columnSpan(0, 0), 3);
            // The window as it opens, then at its smallest.
            for (const QSize size : {QSize(1024, 720), QSize(1, 1)}) {
                panel.window->resize(size);
                QTRY_COMPARE(panel.window->size(), size.expandedTo(panel.window->minimumSize()));
                QApplication::processEvents();
                const QString cut = firstCutText(table);
                QVERIFY2(cut.isEmpty(), qPrintable(QString("%1x%2: %3")
                                                       .arg(panel.window->width())
                                                       .arg(panel.window->height())
                                                       .arg(cut)));
            }
        }
        QApplication::setFont(original);
    }
};

QTEST_MAIN(RestartCollisionsTest)
#include "test_restart_collisions.moc"
