#include "screens/help/ScreenHelpTexts.h"

#include <QCoreApplication>

namespace mtc::screens {

namespace {

// One table for every screen: the texts stay together, so a translation
// (issue 20 §1) finds them in one place. They are the source texts of the
// context "ScreenHelp"; HelpScreen shows their translation.
std::vector<ScreenHelpText> buildTexts() {
    return {
        {"menu",
         QT_TRANSLATE_NOOP("ScreenHelp", "Leads to every screen of the station."),
         "",
         {{QT_TRANSLATE_NOOP("ScreenHelp", "↑ / ↓, Enter"),
           QT_TRANSLATE_NOOP("ScreenHelp", "choose a screen")}}},
        {"position",
         QT_TRANSLATE_NOOP(
             "ScreenHelp",
             "The base screen: where every axis is (workpiece and machine coordinates, distance "
             "to go), feeds and overrides, spindles, the tool and its edge, the active G "
             "functions, the zero offset and the block the machine executes with its "
             "neighbours. In manual mode the axes are jogged here."),
         QT_TRANSLATE_NOOP("ScreenHelp", "the simulator's own layout"),
         {{QT_TRANSLATE_NOOP("ScreenHelp", "↑ / ↓"),
           QT_TRANSLATE_NOOP("ScreenHelp", "choose the axis to jog (manual mode)")},
          {QT_TRANSLATE_NOOP("ScreenHelp", "+ / −"),
           QT_TRANSLATE_NOOP("ScreenHelp", "jog the axis by the step, or while held (continuous)")},
          {QT_TRANSLATE_NOOP("ScreenHelp", "mouse wheel"),
           QT_TRANSLATE_NOOP("ScreenHelp", "handwheel: one detent is one step")},
          {QT_TRANSLATE_NOOP("ScreenHelp", "3 / 4 / 5"),
           QT_TRANSLATE_NOOP("ScreenHelp",
                             "spindle clockwise / counter-clockwise / stop (manual mode)")},
          {QT_TRANSLATE_NOOP("ScreenHelp", "PgUp / PgDn"),
           QT_TRANSLATE_NOOP("ScreenHelp", "spindle speed ±100 rpm (manual mode)")}}},
        {"programs",
         QT_TRANSLATE_NOOP(
             "ScreenHelp",
             "The station's programs with the compiler status bit ( , N, C, E) and the listing "
             "of the one under the cursor; selects the program to run."),
         QT_TRANSLATE_NOOP("ScreenHelp", "seed 001 ch. 7"),
         {{QT_TRANSLATE_NOOP("ScreenHelp", "↑ / ↓"),
           QT_TRANSLATE_NOOP("ScreenHelp", "move the cursor")},
          {QT_TRANSLATE_NOOP("ScreenHelp", "Enter"),
           QT_TRANSLATE_NOOP("ScreenHelp", "select the program")}}},
        {"nc-options",
         QT_TRANSLATE_NOOP(
             "ScreenHelp",
             "The cell's NC options: compiler active, user compilers 1–4, syntax check and the "
             "global macros, written at once to NC_OPTIONS.CFG and GLOBAL_MACROS.MAC."),
         QT_TRANSLATE_NOOP("ScreenHelp", "seed 001 ch. 4, 7, 8"),
         {{QT_TRANSLATE_NOOP("ScreenHelp", "Enter"),
           QT_TRANSLATE_NOOP("ScreenHelp", "change the row under the cursor")},
          {QT_TRANSLATE_NOOP("ScreenHelp", "Delete"),
           QT_TRANSLATE_NOOP("ScreenHelp", "delete the macro under the cursor")},
          {QT_TRANSLATE_NOOP("ScreenHelp", "Escape"),
           QT_TRANSLATE_NOOP("ScreenHelp", "cancel the input line")}}},
        {"editor",
         QT_TRANSLATE_NOOP(
             "ScreenHelp",
             "The NC program editor with highlighting, line numbers and the block of the "
             "cursor; saves atomically and compiles."),
         QT_TRANSLATE_NOOP("ScreenHelp", "seed 001 ch. 10 (source program), ch. 9 (errors)"),
         {{QT_TRANSLATE_NOOP("ScreenHelp", "Ctrl+S"), QT_TRANSLATE_NOOP("ScreenHelp", "save")},
          {QT_TRANSLATE_NOOP("ScreenHelp", "Ctrl+E"),
           QT_TRANSLATE_NOOP("ScreenHelp", "error display")},
          {QT_TRANSLATE_NOOP("ScreenHelp", "Ctrl+W"),
           QT_TRANSLATE_NOOP("ScreenHelp", "graphical NC editor")}}},
        {"errors",
         QT_TRANSLATE_NOOP(
             "ScreenHelp",
             "The error window: one brief message per line (compiler, runtime, restart, MDI) "
             "with program and block; the additional text on request."),
         QT_TRANSLATE_NOOP("ScreenHelp", "seed 001 ch. 9"),
         {{QT_TRANSLATE_NOOP("ScreenHelp", "Enter"),
           QT_TRANSLATE_NOOP("ScreenHelp", "open the editor at the message's line")}}},
        {"gne",
         QT_TRANSLATE_NOOP(
             "ScreenHelp",
             "The graphical NC editor: contours, forms and cycles as rows with their values and "
             "a live drawing; Exit writes them back into the program."),
         QT_TRANSLATE_NOOP("ScreenHelp", "seed 001 ch. 3"),
         {{QT_TRANSLATE_NOOP("ScreenHelp", "↑ / ↓"),
           QT_TRANSLATE_NOOP("ScreenHelp", "choose a row")},
          {QT_TRANSLATE_NOOP("ScreenHelp", "Enter"),
           QT_TRANSLATE_NOOP("ScreenHelp", "take the value")}}},
        {"runtime",
         QT_TRANSLATE_NOOP(
             "ScreenHelp",
             "The source program beside the compiled runtime program; inserted blocks keep "
             "their numbers, compensation corners are marked →."),
         QT_TRANSLATE_NOOP("ScreenHelp", "seed 001 ch. 1, 10, 11"),
         {{QT_TRANSLATE_NOOP("ScreenHelp", "↑ / ↓"),
           QT_TRANSLATE_NOOP("ScreenHelp", "move through the compiled program")}}},
        {"mdi",
         QT_TRANSLATE_NOOP(
             "ScreenHelp",
             "Manual data input: a few NC blocks typed here run from the station's current "
             "state when Start is pressed in MDI mode (Shift+F9). The input stays until an entry "
             "ran to its end."),
         QT_TRANSLATE_NOOP("ScreenHelp", "seed 001 ch. 4, 12"),
         {{QT_TRANSLATE_NOOP("ScreenHelp", "Shift+F9, Shift+F5"),
           QT_TRANSLATE_NOOP("ScreenHelp", "MDI mode, then Start runs the input")}}},
        {"signals",
         QT_TRANSLATE_NOOP("ScreenHelp",
                           "The station's NC and SPS interface signals and a log of every change."),
         QT_TRANSLATE_NOOP("ScreenHelp", "seed 000 ch. 6"),
         {}},
        {"machine-data",
         QT_TRANSLATE_NOOP(
             "ScreenHelp",
             "Machine data pages 30, 60, 61 and the user pages with number, title, value and "
             "unit; values are checked against range, type and write protection."),
         QT_TRANSLATE_NOOP("ScreenHelp", "seed 000 ch. 4; seed 002 ch. 5"),
         {{QT_TRANSLATE_NOOP("ScreenHelp", "← / →"),
           QT_TRANSLATE_NOOP("ScreenHelp", "previous / next page")},
          {QT_TRANSLATE_NOOP("ScreenHelp", "Enter"),
           QT_TRANSLATE_NOOP("ScreenHelp", "edit the value under the cursor")}}},
        {"tools",
         QT_TRANSLATE_NOOP(
             "ScreenHelp",
             "The tool list of the station's process, one row per cutting edge; every value is "
             "checked and saved at once beside the machine data file."),
         QT_TRANSLATE_NOOP("ScreenHelp", "the simulator's own table (docs/TOOL-DATA.md)"),
         {{QT_TRANSLATE_NOOP("ScreenHelp", "cursor keys, Home / End"),
           QT_TRANSLATE_NOOP("ScreenHelp", "move the cell")},
          {QT_TRANSLATE_NOOP("ScreenHelp", "Enter"),
           QT_TRANSLATE_NOOP("ScreenHelp", "edit the cell")}}},
        {"offsets",
         QT_TRANSLATE_NOOP(
             "ScreenHelp",
             "The zero offsets G54..G59 of the station's process, one column per axis "
             "definition."),
         QT_TRANSLATE_NOOP("ScreenHelp", "seed 003, 3.5"),
         {{QT_TRANSLATE_NOOP("ScreenHelp", "cursor keys"),
           QT_TRANSLATE_NOOP("ScreenHelp", "move the cell")},
          {QT_TRANSLATE_NOOP("ScreenHelp", "Enter"),
           QT_TRANSLATE_NOOP("ScreenHelp", "edit the cell")}}},
        {"afc-trend",
         QT_TRANSLATE_NOOP(
             "ScreenHelp",
             "The adaptive feed control's trend over simulated time: torques, limits, feed "
             "reduction and the signals."),
         QT_TRANSLATE_NOOP("ScreenHelp", "seed 002 Fig. 2-1, 6-1"),
         {}},
        {"help",
         QT_TRANSLATE_NOOP("ScreenHelp",
                           "Every key of the panel and the soft keys of each screen."),
         "",
         {}},
        {"restart",
         QT_TRANSLATE_NOOP(
             "ScreenHelp",
             "NC program restart: choose the target block anywhere in the program tree, follow "
             "jumps and calls with Plane+ / Plane−, then start the computing process."),
         QT_TRANSLATE_NOOP("ScreenHelp", "seed 000 ch. 2.3–2.6"),
         {{QT_TRANSLATE_NOOP("ScreenHelp", "↑ / ↓, PgUp / PgDn"),
           QT_TRANSLATE_NOOP("ScreenHelp", "move the cursor")},
          {QT_TRANSLATE_NOOP("ScreenHelp", "Enter"),
           QT_TRANSLATE_NOOP("ScreenHelp", "accept the target block")}}},
        {"restart-result",
         QT_TRANSLATE_NOOP(
             "ScreenHelp",
             "The state the computing process computed for the target beside the machine's "
             "state before, with the differences and the verification of the target."),
         QT_TRANSLATE_NOOP("ScreenHelp", "seed 000 ch. 2.7, 2.8"),
         {}},
        {"repos",
         QT_TRANSLATE_NOOP(
             "ScreenHelp",
             "Distance of every axis to the re-entry point while ADJUST and REPOS run; jogging "
             "in manual mode between them."),
         QT_TRANSLATE_NOOP("ScreenHelp", "seed 000 ch. 2.8, 2.9, Fig. 2-4"),
         {}},
        {"toolpath",
         QT_TRANSLATE_NOOP(
             "ScreenHelp",
             "The selected program's path in 3D (2D without OpenGL): rapid, feed and arcs, the "
             "running block, the restart's target and REPOS path, the programmed contour beside "
             "the tool-centre path under compensation."),
         QT_TRANSLATE_NOOP("ScreenHelp", "the simulator's own view (docs/decisions/toolpath.md)"),
         {{QT_TRANSLATE_NOOP("ScreenHelp", "mouse"),
           QT_TRANSLATE_NOOP("ScreenHelp", "rotate, pan and zoom; a click picks a block")},
          {QT_TRANSLATE_NOOP("ScreenHelp", "0, Home"),
           QT_TRANSLATE_NOOP("ScreenHelp",
                             "frame the part: the cutting moves and the stock (F5 then frames "
                             "every move, the rapids of an approach or tool change too)")},
          {QT_TRANSLATE_NOOP("ScreenHelp", "M"),
           QT_TRANSLATE_NOOP("ScreenHelp",
                             "hide or show the part: the stock cut by the whole program, "
                             "or after Start the part as the tool has cut it so far")}}},
    };
}

}  // namespace

const std::vector<ScreenHelpText>& screenHelpTexts() {
    static const std::vector<ScreenHelpText> texts = buildTexts();
    return texts;
}

const ScreenHelpText* screenHelpText(const QString& name) {
    for (const ScreenHelpText& text : screenHelpTexts())
        if (name == QLatin1String(text.screen)) return &text;
    return nullptr;
}

}  // namespace mtc::screens
