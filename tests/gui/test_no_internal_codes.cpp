// Issue 20: the docs' decision codes ("(NO-005)", "D-014", "C-011") and the
// editor's load timing ("opened in 3 ms") are not for the operator. No screen
// of any station shows one, in English or in German: every label, button,
// list and table cell and the help text (F12) of every screen, the NC options'
// syntax check row with its message, and the editor's message after opening
// a program. The decisions stay in docs/.
#include <QAbstractButton>
#include <QAbstractItemView>
#include <QLabel>
#include <QRegularExpression>
#include <QTextEdit>

#include "PanelFixture.h"

namespace {

/// A decision code of docs/ ("(NO-005)", ", C-011)", "TP-016", "DECISIONS.md
/// D-014") or the editor's load timing; not an NC word with a negative value
/// ("X-100", "C-180": one letter, no closing parenthesis).
const QRegularExpression& internalText() {
    static const QRegularExpression kPattern(
        "[A-Z]{1,4}-[0-9]{3}\\)|\\b[A-Z]{2,4}-[0-9]{3}\\b|DECISIONS\\.md|opened in|geöffnet in");
    return kPattern;
}

/// Every text `root` shows: labels, buttons and their tooltips, the cells of
/// its lists and tables, rich text (help). Program text (the editor's
/// QPlainTextEdit) is the operator's own and not looked at.
QStringList shownTexts(const QWidget* root) {
    QStringList texts;
    for (const auto* label : root->findChildren<QLabel*>())
        if (label->isVisible()) texts << label->text() << label->toolTip();
    for (const auto* button : root->findChildren<QAbstractButton*>())
        if (button->isVisible()) texts << button->text() << button->toolTip();
    for (const auto* view : root->findChildren<QAbstractItemView*>()) {
        const QAbstractItemModel* model = view->isVisible() ? view->model() : nullptr;
        if (!model) continue;
        for (int row = 0; row < std::min(model->rowCount(), 500); ++row)
            for (int column = 0; column < model->columnCount(); ++column)
                texts << model->index(row, column).data().toString();
    }
    for (const auto* text : root->findChildren<QTextEdit*>())
        if (text->isVisible()) texts << text->toPlainText();
    return texts;
}

/// The texts of `texts` with an internal code, "where: text".
QStringList leaks(const QString& where, const QStringList& texts) {
    QStringList found;
    for (const QString& text : texts)
        if (text.contains(internalText())) found << where + ": " + text;
    return found;
}

mtc::hmi::PanelOptions inLanguage(const char* language) {
    mtc::hmi::PanelOptions options;
    options.language = language;
    return options;
}

}  // namespace

class NoInternalCodesTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { useTestSettings(); }

    void thePatternFindsWhatLeakedBefore() {
        QCOMPARE(leaks("probe", {"Syntax check: in the controller at download (NO-005)",
                                 "the simulator's own layout (docs/DECISIONS.md D-014)",
                                 "12 lines opened in 3 ms", "see TP-016", "called as CMD, C-011)",
                                 "N0010 G1 X-100 C-180 F500", "T1 E1", "D-014 Zeile"})
                     .size(),
                 5);
    }

    void everyScreenOfEveryStationAndItsHelp_data() {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << "en";
        QTest::newRow("de") << "de";
    }

    void everyScreenOfEveryStationAndItsHelp() {
        QFETCH(QString, language);
        PanelFixture panel(inLanguage(qPrintable(language)));
        QStringList found;
        int screens = 0;
        for (int station = 0; station < panel.session->processCount(); ++station) {
            panel.window->showStation(station);
            for (const auto& entry : panel.registry.entries()) {
                if (!panel.window->showScreen(entry.name)) continue;
                QApplication::processEvents();
                ++screens;
                found << leaks(entry.name, shownTexts(panel.window.get()));
                panel.press(Qt::Key_F12);  // help for this screen
                QApplication::processEvents();
                found << leaks(entry.name + " help", shownTexts(panel.window.get()));
            }
        }
        QVERIFY(screens > 10);
        QVERIFY2(found.isEmpty(), qPrintable(found.join("\n")));
    }

    void theSyntaxCheckRowAndItsMessage_data() { everyScreenOfEveryStationAndItsHelp_data(); }

    void theSyntaxCheckRowAndItsMessage() {
        QFETCH(QString, language);
        PanelFixture panel(inLanguage(qPrintable(language)));
        QVERIFY(panel.window->showScreen("nc-options"));
        auto* list = child<QAbstractItemView>(panel, "nc-options", "ncoList");
        const QString syntax = language == "de" ? "Syntaxprüfung" : "Syntax check";
        for (int i = 0; i < 10 && !list->currentIndex().data().toString().contains(syntax); ++i)
            panel.press(Qt::Key_Down);
        QVERIFY2(list->currentIndex().data().toString().contains(syntax),
                 qPrintable(list->currentIndex().data().toString()));
        panel.press(Qt::Key_Return);  // says why it has no setting
        const QString message = child<QLabel>(panel, "nc-options", "ncoMessage")->text();
        QVERIFY2(message.contains(language == "de" ? "Download" : "download"), qPrintable(message));
        const QStringList found = leaks("nc-options", shownTexts(panel.window.get()));
        QVERIFY2(found.isEmpty(), qPrintable(found.join("\n")));
    }

    void theEditorSaysHowManyLinesItOpened() {
        PanelFixture panel;
        pickProgram(panel, 1);
        panel.press(Qt::Key_F2);  // edit
        QCOMPARE(panel.window->currentScreenName(), QString("editor"));
        const QString message = child<QLabel>(panel, "editor", "editorMessage")->text();
        QVERIFY2(message.contains("lines opened"), qPrintable(message));
        QVERIFY2(!message.contains(internalText()), qPrintable(message));
    }
};

QTEST_MAIN(NoInternalCodesTest)
#include "test_no_internal_codes.moc"
