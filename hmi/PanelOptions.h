#pragma once

#include <QString>
#include <QStringList>

namespace mtc::hmi {

/// Command-line options of mtc200-panel.
struct PanelOptions {
    QString machineFile;  ///< --machine FILE (empty = built-in demo cell)
    QString programsDir;  ///< --programs DIR (empty = built-in demo programs)
    int process = -1;     ///< --process N (-1 = last used / 0)
    QString program;      ///< --program FILE|NUM
    QString screen;       ///< --screen NAME
    QString screenshot;   ///< --screenshot FILE
    bool run = false;     ///< --run: run the selected program to its end first
    /// --speed 1|10|max: simulated seconds per real second (0 = as fast as possible).
    double speed = 1.0;
    /// --data FILE: machine data file ("-" = keep nothing). When
    /// `dataDefault` is true (set by parsePanelOptions without --data), the
    /// default location of docs/CLI.md is used; a default-constructed
    /// PanelOptions (tests) keeps nothing.
    QString dataFile;
    bool dataDefault = false;
    /// --lang de|en ("" = the desk's setting or locale, docs/DECISIONS.md D-018).
    QString language;
};

/// The value of --lang in `arguments` ("" = none), read before the options
/// are parsed: their own texts (--help, errors) are shown in that language.
QString languageArgument(const QStringList& arguments);

/// True when the command line asks for --help or --version: main() answers
/// those with a QCoreApplication, before any display is opened.
bool onlyAsksForHelp(int argc, const char* const* argv);

/// Parses the arguments (argv[0] included). On a usage error returns false
/// and puts a one-line reason into `error`; --help/--version set `exitNow`.
bool parsePanelOptions(const QStringList& arguments, PanelOptions& options, QString& error,
                       bool& exitNow);

}  // namespace mtc::hmi
