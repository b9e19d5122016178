#include "screens/help/ScreenHelpTexts.h"

namespace mtc::screens {

namespace {

// One table for every screen: the texts stay together, so a translation
// (issue 20 §1) finds them in one place.
std::vector<ScreenHelpText> buildTexts() {
    return {
        {"menu",
         "Leads to every screen of the station.",
         "",
         {{"↑ / ↓, Enter", "choose a screen"}}},
        {"position",
         "The base screen: where every axis is (workpiece and machine coordinates, distance "
         "to go), feeds and overrides, spindles, the tool and its edge, the active G "
         "functions, the zero offset and the block the machine executes with its "
         "neighbours. In manual mode the axes are jogged here.",
         "the simulator's own layout (docs/DECISIONS.md D-014)",
         {{"↑ / ↓", "choose the axis to jog (manual mode)"},
          {"+ / −", "jog the axis by the step, or while held (continuous)"},
          {"mouse wheel", "handwheel: one detent is one step"},
          {"3 / 4 / 5", "spindle clockwise / counter-clockwise / stop (manual mode)"},
          {"PgUp / PgDn", "spindle speed ±100 rpm (manual mode)"}}},
        {"programs",
         "The station's programs with the compiler status bit ( , N, C, E) and the listing "
         "of the one under the cursor; selects the program to run.",
         "seed 001 ch. 7",
         {{"↑ / ↓", "move the cursor"}, {"Enter", "select the program"}}},
        {"nc-options",
         "The cell's NC options: compiler active, user compilers 1–4, syntax check and the "
         "global macros, written at once to NC_OPTIONS.CFG and GLOBAL_MACROS.MAC.",
         "seed 001 ch. 4, 7, 8",
         {{"Enter", "change the row under the cursor"},
          {"Delete", "delete the macro under the cursor"},
          {"Escape", "cancel the input line"}}},
        {"editor",
         "The NC program editor with highlighting, line numbers and the block of the "
         "cursor; saves atomically and compiles.",
         "seed 001 ch. 10 (source program), ch. 9 (errors)",
         {{"Ctrl+S", "save"}, {"Ctrl+E", "error display"}, {"Ctrl+W", "graphical NC editor"}}},
        {"errors",
         "The error window: one brief message per line (compiler, runtime, restart, MDI) "
         "with program and block; the additional text on request.",
         "seed 001 ch. 9",
         {{"Enter", "open the editor at the message's line"}}},
        {"gne",
         "The graphical NC editor: contours, forms and cycles as rows with their values and "
         "a live drawing; Exit writes them back into the program.",
         "seed 001 ch. 3",
         {{"↑ / ↓", "choose a row"}, {"Enter", "take the value"}}},
        {"runtime",
         "The source program beside the compiled runtime program; inserted blocks keep "
         "their numbers, compensation corners are marked →.",
         "seed 001 ch. 1, 10, 11",
         {{"↑ / ↓", "move through the compiled program"}}},
        {"mdi",
         "Manual data input: a few NC blocks typed here run from the station's current "
         "state when Start is pressed in MDI mode (Shift+F9). The input stays until an entry "
         "ran to its end.",
         "seed 001 ch. 4, 12",
         {{"Shift+F9, Shift+F5", "MDI mode, then Start runs the input"}}},
        {"signals",
         "The station's NC and SPS interface signals and a log of every change.",
         "seed 000 ch. 6",
         {}},
        {"machine-data",
         "Machine data pages 30, 60, 61 and the user pages with number, title, value and "
         "unit; values are checked against range, type and write protection.",
         "seed 000 ch. 4; seed 002 ch. 5",
         {{"← / →", "previous / next page"}, {"Enter", "edit the value under the cursor"}}},
        {"tools",
         "The tool list of the station's process, one row per cutting edge; every value is "
         "checked and saved at once beside the machine data file.",
         "the simulator's own table (docs/TOOL-DATA.md)",
         {{"cursor keys, Home / End", "move the cell"}, {"Enter", "edit the cell"}}},
        {"offsets",
         "The zero offsets G54..G59 of the station's process, one column per axis "
         "definition.",
         "seed 003, 3.5",
         {{"cursor keys", "move the cell"}, {"Enter", "edit the cell"}}},
        {"afc-trend",
         "The adaptive feed control's trend over simulated time: torques, limits, feed "
         "reduction and the signals.",
         "seed 002 Fig. 2-1, 6-1",
         {}},
        {"help", "Every key of the panel and the soft keys of each screen.", "", {}},
        {"restart",
         "NC program restart: choose the target block anywhere in the program tree, follow "
         "jumps and calls with Plane+ / Plane−, then start the computing process.",
         "seed 000 ch. 2.3–2.6",
         {{"↑ / ↓, PgUp / PgDn", "move the cursor"}, {"Enter", "accept the target block"}}},
        {"restart-result",
         "The state the computing process computed for the target beside the machine's "
         "state before, with the differences and the verification of the target.",
         "seed 000 ch. 2.7, 2.8",
         {}},
        {"repos",
         "Distance of every axis to the re-entry point while ADJUST and REPOS run; jogging "
         "in manual mode between them.",
         "seed 000 ch. 2.8, 2.9, Fig. 2-4",
         {}},
        {"toolpath",
         "The selected program's path in 3D (2D without OpenGL): rapid, feed and arcs, the "
         "running block, the restart's target and REPOS path, the programmed contour beside "
         "the tool-centre path under compensation.",
         "the simulator's own view (docs/decisions/toolpath.md)",
         {{"mouse", "rotate, pan and zoom; a click picks a block"}}},
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
