#pragma once

#include <QString>
#include <QStringList>

#include "cnc_core/text/Messages.h"

namespace mtc::hmi {

/// The panel's languages: "de" (German, the MTC200's own) and "en".
const QStringList& panelLanguages();

/// The language the panel shows (docs/DECISIONS.md D-018): the --lang
/// option if given, else the desk's setting, else German when the desk's
/// first UI language is German (de_*), English otherwise. `option` and
/// `setting` are "" when absent; an unknown setting is ignored.
QString choosePanelLanguage(const QString& option, const QString& setting,
                            const QStringList& uiLanguages);

/// The desk's stored choice ("" = none), QSettings key "panel/language".
QString storedPanelLanguage();
/// Stores the desk's choice for the next start.
void storePanelLanguage(const QString& language);

/// choosePanelLanguage() over the option, the stored setting and the
/// system locale's UI languages.
QString panelLanguageFor(const QString& option);

/// Loads the embedded catalogue of `language` and installs it in the
/// application (replacing one installed before). English is the source
/// language: its catalogue holds the plural forms only. Returns false
/// with `error` when the catalogue is missing (a broken build).
bool installPanelTranslation(const QString& language, QString& error);

/// The language whose catalogue is installed ("en" before any).
QString installedPanelLanguage();

/// installedPanelLanguage() as the core's value: the language the core's
/// diagnostics are shown in (docs/DECISIONS.md D-023).
mtc::core::Language installedCoreLanguage();

/// A core diagnostic in one line in the installed language (the message
/// lines of the screens; core::messageLine(), docs/DECISIONS.md D-024).
QString coreMessageLine(const mtc::core::Diagnostic& diagnostic);

/// True when the installed catalogue has a translation of `source` in
/// `context` (the test of the core's names, which lupdate cannot see).
bool installedCatalogueHas(const char* context, const char* source);

}  // namespace mtc::hmi
