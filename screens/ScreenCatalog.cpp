#include "screens/ScreenCatalog.h"

#include <QCoreApplication>
#include <memory>

#include "hmi/ProgramWorkspace.h"
#include "hmi/ScreenRegistry.h"
#include "screens/afc_trend/AfcTrendScreen.h"
#include "screens/editor/EditorScreen.h"
#include "screens/editor/ProgramWorkspaces.h"
#include "screens/errors/ErrorsScreen.h"
#include "screens/gne/GneScreen.h"
#include "screens/help/HelpScreen.h"
#include "screens/machine_data/MachineDataScreen.h"
#include "screens/mdi/MdiScreen.h"
#include "screens/menu/MenuScreen.h"
#include "screens/nc_options/NcOptionsScreen.h"
#include "screens/position/PositionScreen.h"
#include "screens/programs/ProgramsScreen.h"
#include "screens/restart/ReposScreen.h"
#include "screens/restart/RestartControllers.h"
#include "screens/restart/RestartResultScreen.h"
#include "screens/restart/RestartScreen.h"
#include "screens/runtime/RuntimeScreen.h"
#include "screens/signals/SignalsScreen.h"
#include "screens/tooldata/ToolTableScreen.h"
#include "screens/tooldata/ZeroOffsetScreen.h"
#include "screens/toolpath/ToolpathLink.h"
#include "screens/toolpath/ToolpathScreen.h"

namespace mtc::screens {

namespace {
/// A screen's title: the same text (context "ScreenTitle") as its title().
QString title(const char* english) {
    return QCoreApplication::translate("ScreenTitle", english);
}
}  // namespace

void registerAllScreens(mtc::hmi::ScreenRegistry& registry) {
    using mtc::hmi::ScreenContext;
    registry.add("menu", title(QT_TRANSLATE_NOOP("ScreenTitle", "Main menu")),
                 [&registry](const ScreenContext& c) { return new MenuScreen(c, &registry); });
    // Program directory, editor, error window and runtime view of a station
    // share one workspace (compile status, error log, program in the editor).
    auto programming = std::make_shared<ProgramWorkspaces>();
    auto restart = std::make_shared<RestartControllers>();
    // The toolpath view is linked to the restart screen or the editor,
    // whichever of them was shown last on the station (TP-012).
    auto links = std::make_shared<ToolpathLinks>();
    registry.add("programs", title(QT_TRANSLATE_NOOP("ScreenTitle", "Program directory")),
                 [programming](const ScreenContext& c) {
                     return new ProgramsScreen(c, programming->forStation(c));
                 });
    registry.add(
        "editor", title(QT_TRANSLATE_NOOP("ScreenTitle", "Program editor")),
        [programming, links](const ScreenContext& c) {
            auto* editor = new EditorScreen(c, programming->forStation(c));
            const auto link = links->attach(editor, ToolpathLink::Partner::Editor);
            QObject::connect(editor, &EditorScreen::cursorLineChanged, link.get(),
                             &ToolpathLink::setEditorCursor);
            return editor;
        },
        false);
    // The graphical NC editor works on the editor's program and line.
    registry.add(
        "gne", title(QT_TRANSLATE_NOOP("ScreenTitle", "Graphical NC editor (GNE)")),
        [programming](const ScreenContext& c) {
            return new GneScreen(c, programming->forStation(c));
        },
        false);
    registry.add("errors", title(QT_TRANSLATE_NOOP("ScreenTitle", "Error display")),
                 [programming, restart](const ScreenContext& c) {
                     return new ErrorsScreen(c, programming->forStation(c), restart->forStation(c));
                 });
    registry.add(
        "runtime", title(QT_TRANSLATE_NOOP("ScreenTitle", "Runtime program")),
        [programming](const ScreenContext& c) {
            return new RuntimeScreen(c, programming->forStation(c));
        },
        false);
    // The cell's NC options (compiler settings, global macros), NO-001.
    registry.add("nc-options", title(QT_TRANSLATE_NOOP("ScreenTitle", "NC options")),
                 [](const ScreenContext& c) { return new NcOptionsScreen(c); });
    // MDI renders the station's MDI session (docs/decisions/mdi.md).
    registry.add("mdi", title(QT_TRANSLATE_NOOP("ScreenTitle", "MDI (manual data input)")),
                 [](const ScreenContext& c) { return new MdiScreen(c); });
    registry.add("signals", title(QT_TRANSLATE_NOOP("ScreenTitle", "Interface signals")),
                 [](const ScreenContext& c) { return new SignalsScreen(c); });
    registry.add("machine-data", title(QT_TRANSLATE_NOOP("ScreenTitle", "Machine data")),
                 [](const ScreenContext& c) { return new MachineDataScreen(c); });
    // Tool table and zero offsets of the station's process (setup data).
    registry.add("tools", title(QT_TRANSLATE_NOOP("ScreenTitle", "Tool table")),
                 [](const ScreenContext& c) { return new ToolTableScreen(c); });
    registry.add("offsets", title(QT_TRANSLATE_NOOP("ScreenTitle", "Zero offsets")),
                 [](const ScreenContext& c) { return new ZeroOffsetScreen(c); });
    registry.add("afc-trend", title(QT_TRANSLATE_NOOP("ScreenTitle", "Adaptive feed trend")),
                 [](const ScreenContext& c) { return new AfcTrendScreen(c); });
    registry.add("help", title(QT_TRANSLATE_NOOP("ScreenTitle", "Help")),
                 [](const ScreenContext& c) { return new HelpScreen(c); });
    // The restart screens of a station share one controller (selection,
    // computing process, result).
    registry.add("restart", title(QT_TRANSLATE_NOOP("ScreenTitle", "NC program restart")),
                 [restart, links](const ScreenContext& c) {
                     auto* screen = new RestartScreen(c, restart->forStation(c));
                     links->attach(screen, ToolpathLink::Partner::Restart);
                     return screen;
                 });
    registry.add(
        "restart-result", title(QT_TRANSLATE_NOOP("ScreenTitle", "NC program restart: result")),
        [restart](const ScreenContext& c) {
            return new RestartResultScreen(c, restart->forStation(c));
        },
        false);
    registry.add(
        "repos", title(QT_TRANSLATE_NOOP("ScreenTitle", "Repositioning")),
        [restart](const ScreenContext& c) { return new ReposScreen(c, restart->forStation(c)); },
        false);
    // The toolpath view follows (and moves) the cursor of the restart screen
    // or of the editor; a pick for the editor goes through the workspace.
    registry.add("toolpath", title(QT_TRANSLATE_NOOP("ScreenTitle", "Toolpath graphics")),
                 [restart, programming, links](const ScreenContext& c) {
                     const auto link = links->forStation(c);
                     const auto workspace = programming->forStation(c);
                     auto* screen = new ToolpathScreen(c, restart->forStation(c), link);
                     QObject::connect(link.get(), &ToolpathLink::editorLineRequested, screen,
                                      [workspace](int program, int line) {
                                          workspace->requestEdit(program, line);
                                      });
                     return screen;
                 });
    // The base screen: the station's first screen after start-up (F11 from
    // anywhere). Last in the menu so the other screens keep their soft keys.
    registry.add("position", title(QT_TRANSLATE_NOOP("ScreenTitle", "Base screen (position)")),
                 [](const ScreenContext& c) { return new PositionScreen(c); });
}

}  // namespace mtc::screens
