#include "screens/restart/RestartControllers.h"

#include "hmi/CellSession.h"
#include "screens/restart/RestartController.h"

namespace mtc::screens {

std::shared_ptr<RestartController> RestartControllers::forStation(
    const mtc::hmi::ScreenContext& context) {
    std::weak_ptr<RestartController>& slot = controllers_[{context.session, context.process}];
    std::shared_ptr<RestartController> controller = slot.lock();
    if (!controller) {
        controller = std::make_shared<RestartController>(context.session, context.process);
        slot = controller;
    }
    return controller;
}

}  // namespace mtc::screens
