#include "screens/ScreenCatalog.h"

#include <memory>

#include "hmi/ScreenRegistry.h"
#include "screens/help/HelpScreen.h"
#include "screens/machine_data/MachineDataScreen.h"
#include "screens/menu/MenuScreen.h"
#include "screens/programs/ProgramsScreen.h"
#include "screens/restart/ReposScreen.h"
#include "screens/restart/RestartControllers.h"
#include "screens/restart/RestartResultScreen.h"
#include "screens/restart/RestartScreen.h"
#include "screens/signals/SignalsScreen.h"
#include "screens/toolpath/ToolpathScreen.h"

namespace mtc::screens {

void registerAllScreens(mtc::hmi::ScreenRegistry& registry) {
    using mtc::hmi::ScreenContext;
    registry.add("menu", "Main menu",
                 [&registry](const ScreenContext& c) { return new MenuScreen(c, &registry); });
    registry.add("programs", "Program directory",
                 [](const ScreenContext& c) { return new ProgramsScreen(c); });
    registry.add("signals", "Interface signals",
                 [](const ScreenContext& c) { return new SignalsScreen(c); });
    registry.add("machine-data", "Machine data",
                 [](const ScreenContext& c) { return new MachineDataScreen(c); });
    registry.add("help", "Key assignments",
                 [](const ScreenContext& c) { return new HelpScreen(c); });
    // The restart screens of a station share one controller (selection,
    // computing process, result).
    auto restart = std::make_shared<RestartControllers>();
    registry.add("restart", "NC program restart", [restart](const ScreenContext& c) {
        return new RestartScreen(c, restart->forStation(c));
    });
    registry.add(
        "restart-result", "NC program restart: result",
        [restart](const ScreenContext& c) {
            return new RestartResultScreen(c, restart->forStation(c));
        },
        false);
    registry.add(
        "repos", "Repositioning",
        [restart](const ScreenContext& c) { return new ReposScreen(c, restart->forStation(c)); },
        false);
    // The toolpath view follows (and moves) the restart screen's cursor.
    registry.add("toolpath", "Toolpath graphics", [restart](const ScreenContext& c) {
        return new ToolpathScreen(c, restart->forStation(c));
    });
}

}  // namespace mtc::screens
