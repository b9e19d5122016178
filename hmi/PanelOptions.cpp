#include "hmi/PanelOptions.h"

#include <QCommandLineParser>
#include <QCoreApplication>

namespace mtc::hmi {

namespace {
/// The options' texts, context "PanelOptions" of the catalogues.
struct Text {
    Q_DECLARE_TR_FUNCTIONS(PanelOptions)
};
}  // namespace

bool parsePanelOptions(const QStringList& arguments, PanelOptions& options, QString& error,
                       bool& exitNow) {
    exitNow = false;
    QCommandLineParser parser;
    parser.setApplicationDescription(Text::tr("MTC200 operator panel simulator"));
    auto help = parser.addHelpOption();
    auto version = parser.addVersionOption();
    parser.addOptions({
        {"machine", Text::tr("Machine configuration file (default: built-in demo cell)."), "FILE"},
        {"programs",
         Text::tr("Program directory with NuxxYzzz.DAT files (default: demo programs)."), "DIR"},
        {"process", Text::tr("Station (process) shown first."), "N"},
        {"program", Text::tr("Program to select: a number or a source file."), "FILE|NUM"},
        {"screen", Text::tr("Screen shown first (restart, programs, signals, help, ...)."), "NAME"},
        {"screenshot", Text::tr("Render the screen once, write a PNG to FILE and exit."), "FILE"},
        {"run",
         Text::tr("Run the selected program of the station to its end in simulated time before "
                  "the window appears (e.g. a trend for --screenshot).")},
        {"speed",
         Text::tr("Simulation speed: 1 (real time, default), 10 (ten times) or max (as fast as "
                  "possible); the Speed key changes it."),
         "1|10|max"},
        {"data",
         Text::tr("Machine data file (default: $XDG_STATE_HOME/mtc200/machine-data/<cell>.mdt; "
                  "'-' keeps nothing)."),
         "FILE"},
        {"lang",
         Text::tr(
             "Language of the panel: de (German) or en (English). Default: the language chosen "
             "on the help screen, else the desk's locale (German for de_*)."),
         "de|en"},
    });
    if (!parser.parse(arguments)) {
        error = parser.errorText();
        return false;
    }
    if (parser.isSet(help)) {
        exitNow = true;
        error = parser.helpText();
        return true;
    }
    if (parser.isSet(version)) {
        exitNow = true;
        error = QCoreApplication::applicationName() + " " + QCoreApplication::applicationVersion() +
                "\n";
        return true;
    }
    if (!parser.positionalArguments().isEmpty()) {
        error = Text::tr("unexpected argument: %1").arg(parser.positionalArguments().first());
        return false;
    }
    options.machineFile = parser.value("machine");
    options.programsDir = parser.value("programs");
    options.program = parser.value("program");
    options.screen = parser.value("screen");
    options.screenshot = parser.value("screenshot");
    options.run = parser.isSet("run");
    options.dataFile = parser.value("data");
    options.dataDefault = !parser.isSet("data");
    if (parser.isSet("data") && options.dataFile.isEmpty()) {
        error = Text::tr("--data needs a file (or '-' for none)");
        return false;
    }
    if (parser.isSet("speed")) {
        const QString speed = parser.value("speed").trimmed().toLower();
        if (speed == "max") {
            options.speed = 0.0;
        } else if (speed == "1" || speed == "10") {
            options.speed = speed.toDouble();
        } else {
            error = Text::tr("--speed needs 1, 10 or max, got '%1'").arg(parser.value("speed"));
            return false;
        }
    }
    if (parser.isSet("lang")) {
        options.language = parser.value("lang").trimmed().toLower();
        if (options.language != "de" && options.language != "en") {
            error = Text::tr("--lang needs de or en, got '%1'").arg(parser.value("lang"));
            return false;
        }
    }
    if (parser.isSet("process")) {
        bool ok = false;
        options.process = parser.value("process").toInt(&ok);
        if (!ok || options.process < 0) {
            error = Text::tr("--process needs a process number >= 0, got '%1'")
                        .arg(parser.value("process"));
            return false;
        }
    }
    return true;
}

QString languageArgument(const QStringList& arguments) {
    for (int i = 1; i < arguments.size(); ++i) {
        if (arguments[i] == "--lang" || arguments[i] == "-lang")
            return arguments.value(i + 1).trimmed().toLower();
        if (arguments[i].startsWith("--lang=")) return arguments[i].mid(7).trimmed().toLower();
    }
    return {};
}

bool onlyAsksForHelp(int argc, const char* const* argv) {
    for (int i = 1; i < argc; ++i) {
        const QByteArray argument(argv[i]);
        if (argument == "-h" || argument == "--help" || argument == "-?" ||
            argument == "--help-all" || argument == "-v" || argument == "--version")
            return true;
    }
    return false;
}

}  // namespace mtc::hmi
