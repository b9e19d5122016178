#include "screens/ScreenCatalog.h"

#include <memory>

#include "hmi/ScreenRegistry.h"
#include "screens/help/HelpScreen.h"
#include "screens/menu/MenuScreen.h"
#include "screens/programs/ProgramsScreen.h"
#include "screens/restart/RestartControllers.h"
#include "screens/restart/RestartScreen.h"
#include "screens/signals/SignalsScreen.h"

namespace mtc::screens {

void registerAllScreens(mtc::hmi::ScreenRegistry& registry) {
    using mtc::hmi::ScreenContext;
    registry.add("menu", "Main menu",
                 [&registry](const ScreenContext& c) { return new MenuScreen(c, &registry); });
    registry.add("programs", "Program directory",
                 [](const ScreenContext& c) { return new ProgramsScreen(c); });
    registry.add("signals", "Interface signals",
                 [](const ScreenContext& c) { return new SignalsScreen(c); });
    registry.add("help", "Key assignments",
                 [](const ScreenContext& c) { return new HelpScreen(c); });
    // The restart screens of a station share one controller (selection,
    // computing process, result).
    auto restart = std::make_shared<RestartControllers>();
    registry.add("restart", "NC program restart", [restart](const ScreenContext& c) {
        return new RestartScreen(c, restart->forStation(c));
    });
}

}  // namespace mtc::screens
