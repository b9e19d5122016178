#pragma once

#include <QMap>
#include <QPair>
#include <memory>

#include "hmi/Screen.h"

namespace mtc::screens {

class RestartController;

/// Hands every restart screen of a station the same RestartController, so
/// the selection, the computing process and its result are shared by the
/// restart, restart-result and repos screens of that station (and kept per
/// station). The screens own it together: it goes with the last of them,
/// i.e. with the window, before the cell session it works on.
class RestartControllers {
  public:
    /// The controller of the context's station; created on first use.
    std::shared_ptr<RestartController> forStation(const mtc::hmi::ScreenContext& context);

  private:
    QMap<QPair<const void*, int>, std::weak_ptr<RestartController>> controllers_;
};

}  // namespace mtc::screens
