#include "hmi/PanelLanguage.h"

#include <QCoreApplication>
#include <QLocale>
#include <QSettings>
#include <QTranslator>
#include <memory>

// The catalogues are a Qt resource of the static library mtc_translations
// (resources/translations); a static library's resources are registered by
// hand. Q_INIT_RESOURCE must be called outside any namespace.
static void registerTranslationResource() {
    Q_INIT_RESOURCE(mtc200_translations);
}

namespace mtc::hmi {

namespace {
const char* const kLanguageKey = "panel/language";
const char* const kTranslatorName = "mtc200PanelTranslator";

/// The panel's translator: a child of the application object (no global).
QTranslator* installedTranslator() {
    QCoreApplication* app = QCoreApplication::instance();
    return app ? app->findChild<QTranslator*>(kTranslatorName, Qt::FindDirectChildrenOnly)
               : nullptr;
}
}  // namespace

const QStringList& panelLanguages() {
    static const QStringList languages{"de", "en"};
    return languages;
}

QString choosePanelLanguage(const QString& option, const QString& setting,
                            const QStringList& uiLanguages) {
    if (panelLanguages().contains(option)) return option;
    if (panelLanguages().contains(setting)) return setting;
    const QString first = uiLanguages.value(0).toLower();
    return first == "de" || first.startsWith("de-") || first.startsWith("de_") ? "de" : "en";
}

QString storedPanelLanguage() {
    return QSettings().value(kLanguageKey).toString();
}

void storePanelLanguage(const QString& language) {
    QSettings().setValue(kLanguageKey, language);
}

QString panelLanguageFor(const QString& option) {
    return choosePanelLanguage(option, storedPanelLanguage(), QLocale::system().uiLanguages());
}

bool installPanelTranslation(const QString& language, QString& error) {
    registerTranslationResource();
    auto translator = std::make_unique<QTranslator>();
    if (!translator->load(":/translations/mtc200_" + language + ".qm")) {
        error = QString("no translation catalogue for language '%1'").arg(language);
        return false;
    }
    if (QTranslator* old = installedTranslator()) {
        QCoreApplication::removeTranslator(old);
        delete old;
    }
    translator->setObjectName(kTranslatorName);
    translator->setProperty("language", language);
    translator->setParent(QCoreApplication::instance());
    QCoreApplication::installTranslator(translator.release());
    return true;
}

bool installedCatalogueHas(const char* context, const char* source) {
    const QTranslator* translator = installedTranslator();
    return translator && !translator->translate(context, source).isEmpty();
}

QString installedPanelLanguage() {
    const QTranslator* translator = installedTranslator();
    return translator ? translator->property("language").toString() : QString("en");
}

mtc::core::Language installedCoreLanguage() {
    return mtc::core::languageFromTag(installedPanelLanguage().toStdString())
        .value_or(mtc::core::Language::English);
}

QString coreMessageLine(const mtc::core::Diagnostic& diagnostic) {
    return QString::fromStdString(mtc::core::messageLine(diagnostic, installedCoreLanguage()));
}

}  // namespace mtc::hmi
