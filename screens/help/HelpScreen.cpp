#include "screens/help/HelpScreen.h"

#include <QTextBrowser>
#include <QVBoxLayout>

#include "hmi/KeyMap.h"
#include "hmi/PanelLanguage.h"
#include "screens/help/ScreenHelpTexts.h"

namespace mtc::screens {

namespace {

QString softKeyRows(mtc::hmi::Screen& screen) {
    QString rows;
    const auto keys = screen.softKeys();
    for (int i = 0; i < keys.size(); ++i) {
        if (keys[i].label.isEmpty()) continue;
        rows += QString("<tr><td><b>F%1</b></td><td>%2</td></tr>")
                    .arg(i + 1)
                    .arg(QString(keys[i].label).replace('\n', ' ').toHtmlEscaped());
    }
    return rows;
}

/// A text of the help table in the language of the panel.
QString helpText(const char* english) {
    return QCoreApplication::translate("ScreenHelp", english);
}

/// The name of a panel language in that language (never translated).
QString nativeName(const QString& language) {
    return language == "de" ? QString::fromUtf8("Deutsch") : QString("English");
}

QString row(const QString& keys, const QString& meaning) {
    return QString("<tr><td><b>%1</b></td><td>%2</td></tr>")
        .arg(keys.toHtmlEscaped(), meaning.toHtmlEscaped());
}

}  // namespace

HelpScreen::HelpScreen(const mtc::hmi::ScreenContext& context) : Screen(context) {
    auto* layout = new QVBoxLayout(this);
    text_ = new QTextBrowser(this);
    text_->setObjectName("helpText");
    layout->addWidget(text_);
    setFocusProxy(text_);
}

mtc::hmi::Screen* HelpScreen::stationScreen(const QString& name) const {
    if (name.isEmpty() || !context().stationScreens) return nullptr;
    for (mtc::hmi::Screen* screen : context().stationScreens())
        if (screen != this && screen->screenName() == name) return screen;
    return nullptr;
}

QString HelpScreen::screenHelpHtml(mtc::hmi::Screen& screen) const {
    QString html = QString("<h3>%1</h3>").arg(screen.title().toHtmlEscaped());
    if (const ScreenHelpText* help = screenHelpText(screen.screenName())) {
        html += "<p>" + helpText(help->purpose).toHtmlEscaped() + "</p>";
        if (*help->seed)
            html += "<p><i>" + tr("Reproduces: %1").arg(helpText(help->seed)).toHtmlEscaped() +
                    "</i></p>";
        html += "<table cellpadding='3'>" + softKeyRows(screen);
        for (const HelpKey& key : help->keys)
            html += row(helpText(key.keys), helpText(key.meaning));
        return html + "</table>";
    }
    return html + "<table cellpadding='3'>" + softKeyRows(screen) + "</table>";
}

QString HelpScreen::overviewHtml() const {
    QString html;
    if (!context().stationScreens) return html;
    for (mtc::hmi::Screen* screen : context().stationScreens()) {
        if (screen == this) continue;
        html += QString("<h4>%1 (%2)</h4><table cellpadding='2'>")
                    .arg(screen->title().toHtmlEscaped(), screen->screenName());
        html += softKeyRows(*screen) + "</table>";
    }
    return html;
}

QString HelpScreen::helpHtml() const {
    QString html;
    if (mtc::hmi::Screen* screen = stationScreen(subject_)) html += screenHelpHtml(*screen);
    html += "<h3>" + tr("Panel keys") + "</h3><table cellpadding='3'>";
    for (const auto& a : mtc::hmi::globalKeyAssignments())
        html += row(a.keys, a.meaning);
    html += "</table>";
    if (subject_.isEmpty()) html += overviewHtml();
    return html + languageHtml();
}

QString HelpScreen::languageHtml() const {
    const QString stored = mtc::hmi::storedPanelLanguage();
    QString html =
        "<h3>" + tr("Language") + "</h3><p>" +
        tr("The panel is shown in %1.").arg(nativeName(mtc::hmi::installedPanelLanguage())) + " ";
    if (stored.isEmpty())
        html +=
            tr("This desk has no language of its own: the panel follows the desk's locale "
               "(German for de_*) unless started with --lang de|en.");
    else
        html += tr("This desk starts the panel in %1 (unless started with --lang de|en).")
                    .arg(nativeName(stored));
    return html + " " + tr("F6 and F7 store the language for the next start.") + "</p>";
}

void HelpScreen::storeLanguage(const QString& language) {
    mtc::hmi::storePanelLanguage(language);
    text_->setHtml(helpHtml());
}

void HelpScreen::activated() {
    // The screen the operator pressed F12 on; from the menu, every screen.
    const QString previous = context().previousScreen ? context().previousScreen() : QString();
    subject_ = previous == "menu" || !stationScreen(previous) ? QString() : previous;
    text_->setHtml(helpHtml());
}

mtc::hmi::SoftKeys HelpScreen::softKeys() {
    mtc::hmi::SoftKeys keys(8);
    // The desk's language for the next start (D-018); the screens keep the
    // language they were built in until then.
    keys[5] = {nativeName("de"), [this] { storeLanguage("de"); }};
    keys[6] = {nativeName("en"), [this] { storeLanguage("en"); }};
    keys[7] = {tr("Back"), [this] { emit navigateTo(subject_.isEmpty() ? "menu" : subject_); }};
    return keys;
}

}  // namespace mtc::screens
