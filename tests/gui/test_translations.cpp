// The panel in German and English (issue 20 §1, docs/DECISIONS.md D-018):
// the language choice, the German texts of the core's names (which lupdate
// cannot see; i18n.translations_complete checks the rest), and the real
// panel in German: every screen's title and soft keys differ from English
// except the words both languages share, and no soft key or M key label is
// clipped at the default window size.
#include <QLabel>
#include <QPushButton>
#include <QTextBrowser>

#include "PanelFixture.h"
#include "cnc_core/cell/StationStatus.h"
#include "cnc_core/interp/ModalGroups.h"
#include "hmi/KeyMap.h"
#include "hmi/PanelLanguage.h"
#include "hmi/Screen.h"
#include "hmi/SoftKeyBar.h"
#include "hmi/SoftKeyButton.h"

namespace {

using Texts = QMap<QString, QString>;  // "screen/F3" -> label, "screen/title" -> title

/// Every screen of station 0 with its title and soft key labels.
Texts visibleTexts(PanelFixture& panel) {
    Texts texts;
    for (const auto& entry : panel.registry.entries()) {
        texts[entry.name + "/menu"] = entry.title;
        if (!panel.window->showScreen(entry.name)) continue;
        mtc::hmi::Screen* screen = panel.window->currentScreen();
        texts[entry.name + "/title"] = screen->title();
        const auto keys = screen->softKeys();
        for (int i = 0; i < keys.size(); ++i)
            if (!keys[i].label.isEmpty())
                texts[QString("%1/F%2").arg(entry.name).arg(i + 1)] = keys[i].label;
    }
    return texts;
}

/// Labels the same in German and English (names, codes, borrowed words).
bool sameInBothLanguages(const QString& label) {
    static const QStringList shared{"MDI",    "REPOS",       "Start",       "Stop",
                                    "GNE",    "Deutsch",     "English",     "Editor",
                                    "Signal", "Export\nPNG", "Export\nCSV", "Alter-\nnative"};
    return shared.contains(label) || !label.contains(QRegularExpression("[a-z]{3}"));
}

}  // namespace

class TranslationsTest : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { useTestSettings(); }

    void languageFromOptionSettingOrLocale() {
        using mtc::hmi::choosePanelLanguage;
        QCOMPARE(choosePanelLanguage("", "", {"de-DE", "de"}), QString("de"));
        QCOMPARE(choosePanelLanguage("", "", {"de-AT"}), QString("de"));
        QCOMPARE(choosePanelLanguage("", "", {"en-US"}), QString("en"));
        QCOMPARE(choosePanelLanguage("", "", {"fr-FR", "de-DE"}), QString("en"));
        QCOMPARE(choosePanelLanguage("", "", {}), QString("en"));
        QCOMPARE(choosePanelLanguage("", "de", {"en-GB"}), QString("de"));  // the desk's setting
        QCOMPARE(choosePanelLanguage("", "en", {"de-DE"}), QString("en"));
        QCOMPARE(choosePanelLanguage("", "fr", {"de-DE"}), QString("de"));    // unknown setting
        QCOMPARE(choosePanelLanguage("en", "de", {"de-DE"}), QString("en"));  // --lang wins
        QCOMPARE(choosePanelLanguage("de", "en", {"en-US"}), QString("de"));
    }

    void optionIsCheckedAndStoredSettingIsUsed() {
        mtc::hmi::PanelOptions options;
        QString error;
        bool exitNow = false;
        QVERIFY(
            mtc::hmi::parsePanelOptions({"mtc200-panel", "--lang", "de"}, options, error, exitNow));
        QCOMPARE(options.language, QString("de"));
        QVERIFY(!mtc::hmi::parsePanelOptions({"mtc200-panel", "--lang", "fr"}, options, error,
                                             exitNow));
        QVERIFY2(error.contains("--lang needs de or en"), qPrintable(error));
        QCOMPARE(mtc::hmi::languageArgument({"p", "--lang=EN"}), QString("en"));
        QCOMPARE(mtc::hmi::languageArgument({"p", "--lang", "de", "--run"}), QString("de"));
        mtc::hmi::storePanelLanguage("de");
        QCOMPARE(mtc::hmi::panelLanguageFor(""), QString("de"));
        QCOMPARE(mtc::hmi::panelLanguageFor("en"), QString("en"));
        mtc::hmi::storePanelLanguage("en");
        QCOMPARE(mtc::hmi::panelLanguageFor(""), QString("en"));
        QSettings().remove("panel/language");
    }

    void everyNameOfTheCoreHasAGermanText() {
        QString error;
        QVERIFY2(mtc::hmi::installPanelTranslation("de", error), qPrintable(error));
        QStringList missing;
        const auto need = [&](const char* english) {
            const QByteArray text(english);
            if (text.isEmpty() || text == "-") return;
            if (!mtc::hmi::installedCatalogueHas("CoreTerms", english)) missing << english;
        };
        using namespace mtc::core;
        for (ControlKey key : mtc::hmi::machineKeys())
            need(keyName(key));
        for (OperatingMode mode :
             {OperatingMode::Automatic, OperatingMode::Manual, OperatingMode::Mdi})
            need(modeName(mode));
        for (int s = static_cast<int>(ProgramState::NoProgram);
             s <= static_cast<int>(ProgramState::Error); ++s) {
            need(programStateWord(static_cast<ProgramState>(s)));
            need(programStateName(static_cast<ProgramState>(s)));
        }
        for (int t = static_cast<int>(SpindleTurn::Unknown);
             t <= static_cast<int>(SpindleTurn::Oriented); ++t)
            need(spindleTurnName(static_cast<SpindleTurn>(t)));
        for (int group : usedGGroups())
            need(gGroupName(group).brief);
        QVERIFY2(missing.isEmpty(), qPrintable("no German text for: " + missing.join(", ")));
        QVERIFY(!mtc::hmi::installedCatalogueHas("CoreTerms", "a name the core does not have"));
    }

    void germanPanelTranslatesEveryScreen() {
        Texts english;
        {
            PanelFixture panel;  // English
            english = visibleTexts(panel);
        }
        mtc::hmi::PanelOptions options;
        options.language = "de";
        PanelFixture panel(options);
        QCOMPARE(mtc::hmi::installedPanelLanguage(), QString("de"));
        const Texts german = visibleTexts(panel);
        QCOMPARE(german.keys(), english.keys());
        QStringList untranslated;
        for (auto it = german.begin(); it != german.end(); ++it)
            if (it.value() == english.value(it.key()) && !sameInBothLanguages(it.value()))
                untranslated << it.key() + " = " + it.value();
        QVERIFY2(untranslated.isEmpty(),
                 qPrintable("English in German: " + untranslated.join("; ")));
        QCOMPARE(german.value("menu/title"), QString("Hauptmenü"));
        QCOMPARE(german.value("restart/menu"), QString("Satzvorlauf"));
        auto* reset = panel.window->findChild<QPushButton*>("mkey-7");
        QCOMPARE(reset->text().simplified(), QString("Steuerung rücksetzen"));  // may take 2 lines
    }

    // The compile refusals come from the core as a reason, worded by the
    // panel in the operator's language.
    void germanCompileRefusal() {
        mtc::hmi::PanelOptions options;
        options.language = "de";
        PanelFixture panel(options);
        pickProgram(panel, 1);    // a built-in program without compiler keywords
        panel.press(Qt::Key_F6);  // Compiler active = Ja
        panel.press(Qt::Key_F3);  // Compile
        auto* message = child<QLabel>(panel, "programs", "programsMessage");
        QCOMPARE(
            message->text(),
            QString("das Programm verwendet kein Compiler-Schlüsselwort: nichts zu compilieren"));
        panel.press(Qt::Key_F6);  // back to No for the other cases
    }

    // F12 in German: the screen's help text, its seed section and the panel's
    // keys in German (issue 20 §4); F6 / F7 store the desk's language.
    void germanHelpAndTheLanguageKeys() {
        QSettings().remove("panel/language");
        mtc::hmi::PanelOptions options;
        options.language = "de";
        PanelFixture panel(options);
        panel.window->showScreen("tools");
        panel.press(Qt::Key_F12);
        QCOMPARE(panel.window->currentScreenName(), QString("help"));
        auto* text = panel.window->screen(0, "help")->findChild<QTextBrowser*>("helpText");
        QString shown = text->toPlainText();
        QVERIFY2(shown.contains("Die Werkzeugliste des Prozesses der Station"), qPrintable(shown));
        QVERIFY2(shown.contains("Bildet nach: eigene Tabelle des Simulators"), qPrintable(shown));
        QVERIFY2(shown.contains("Tasten des Bedienfelds"), qPrintable(shown));
        QVERIFY2(shown.contains("Maschinensteuertaste „Einzelsatz“"), qPrintable(shown));
        QVERIFY2(shown.contains("Das Bedienfeld wird auf Deutsch angezeigt."), qPrintable(shown));
        QVERIFY(!shown.contains("The tool list"));
        panel.press(Qt::Key_F7);  // English from the next start
        QCOMPARE(mtc::hmi::storedPanelLanguage(), QString("en"));
        shown = text->toPlainText();
        QVERIFY2(shown.contains("startet das Bedienfeld auf English"), qPrintable(shown));
        panel.press(Qt::Key_F6);
        QCOMPARE(mtc::hmi::storedPanelLanguage(), QString("de"));
        QCOMPARE(mtc::hmi::installedPanelLanguage(), QString("de"));  // until the next start
        QSettings().remove("panel/language");
    }

    // At the default size and at the smallest the window allows.
    void germanLabelsAreNotClipped_data() {
        QTest::addColumn<bool>("smallest");
        QTest::newRow("default size") << false;
        QTest::newRow("minimum size") << true;
    }

    void germanLabelsAreNotClipped() {
        QFETCH(bool, smallest);
        mtc::hmi::PanelOptions options;
        options.language = "de";
        PanelFixture panel(options);
        if (smallest) panel.window->resize(panel.window->minimumSizeHint());
        QApplication::processEvents();
        QStringList clipped;
        for (const auto& entry : panel.registry.entries()) {
            panel.window->showScreen(entry.name);
            QApplication::processEvents();
            for (auto* key : panel.window->softKeyBar()->findChildren<mtc::hmi::SoftKeyButton*>())
                if (key->shortened())
                    clipped << entry.name + "/" + key->objectName() + " " + key->label();
        }
        for (auto* key : panel.window->findChildren<QPushButton*>(QRegularExpression("^mkey-")))
            for (const QString& line : key->text().split('\n'))
                if (key->fontMetrics().horizontalAdvance(line) > key->contentsRect().width())
                    clipped << key->objectName() + " " + key->text();
        QVERIFY2(clipped.isEmpty(), qPrintable("clipped: " + clipped.join("; ")));
    }
};

QTEST_MAIN(TranslationsTest)
#include "test_translations.moc"
