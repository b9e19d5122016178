#include "screens/editor/ProgramWorkspaces.h"

#include "hmi/ProgramWorkspace.h"

namespace mtc::screens {

std::shared_ptr<mtc::hmi::ProgramWorkspace> ProgramWorkspaces::forStation(
    const mtc::hmi::ScreenContext& context) {
    const QPair<const void*, int> key(context.session, context.process);
    if (auto existing = workspaces_.value(key).lock()) return existing;
    auto workspace = std::make_shared<mtc::hmi::ProgramWorkspace>(context.session, context.process);
    workspaces_[key] = workspace;
    return workspace;
}

}  // namespace mtc::screens
