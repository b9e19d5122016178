#include "screens/help/HelpScreen.h"

#include <QTextBrowser>
#include <QVBoxLayout>

#include "hmi/KeyMap.h"

namespace mtc::screens {

HelpScreen::HelpScreen(const mtc::hmi::ScreenContext& context) : Screen(context) {
    auto* layout = new QVBoxLayout(this);
    text_ = new QTextBrowser(this);
    text_->setObjectName("helpText");
    layout->addWidget(text_);
    setFocusProxy(text_);
}

QString HelpScreen::helpHtml() const {
    QString html = "<h3>Panel keys</h3><table cellpadding='3'>";
    for (const auto& a : mtc::hmi::globalKeyAssignments())
        html += QString("<tr><td><b>%1</b></td><td>%2</td></tr>")
                    .arg(a.keys.toHtmlEscaped(), a.meaning.toHtmlEscaped());
    html += "</table>";
    if (!context().stationScreens) return html;
    for (mtc::hmi::Screen* screen : context().stationScreens()) {
        if (screen == this) continue;
        html += QString("<h4>%1 (%2)</h4><table cellpadding='2'>")
                    .arg(screen->title().toHtmlEscaped(), screen->screenName());
        const auto keys = screen->softKeys();
        for (int i = 0; i < keys.size(); ++i) {
            if (keys[i].label.isEmpty()) continue;
            html += QString("<tr><td><b>F%1</b></td><td>%2</td></tr>")
                        .arg(i + 1)
                        .arg(QString(keys[i].label).replace('\n', ' ').toHtmlEscaped());
        }
        html += "</table>";
    }
    return html;
}

void HelpScreen::activated() {
    text_->setHtml(helpHtml());
}

mtc::hmi::SoftKeys HelpScreen::softKeys() {
    mtc::hmi::SoftKeys keys(8);
    keys[7] = {"Back", [this] { emit navigateTo("menu"); }};
    return keys;
}

}  // namespace mtc::screens
