#pragma once

namespace mtc::hmi {
class ScreenRegistry;
}

namespace mtc::screens {

/// Registers every screen of the product with the panel (menu first).
void registerAllScreens(mtc::hmi::ScreenRegistry& registry);

}  // namespace mtc::screens
