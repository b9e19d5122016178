#include "screens/restart/RestartControllers.h"

#include "hmi/CellSession.h"
#include "screens/restart/RestartController.h"

namespace mtc::screens {

RestartController* RestartControllers::forStation(const mtc::hmi::ScreenContext& context) {
    QPointer<RestartController>& slot = controllers_[{context.session, context.process}];
    if (!slot) slot = new RestartController(context.session, context.process, context.session);
    return slot;
}

}  // namespace mtc::screens
