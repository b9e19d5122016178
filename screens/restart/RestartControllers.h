#pragma once

#include <QMap>
#include <QPair>
#include <QPointer>

#include "hmi/Screen.h"

namespace mtc::screens {

class RestartController;

/// Hands every restart screen of a station the same RestartController, so
/// the selection, the computing process and its result are shared by the
/// restart, restart-result and repos screens of that station (and kept per
/// station). The controllers belong to the cell session (QObject children).
class RestartControllers {
  public:
    /// The controller of the context's station; created on first use.
    RestartController* forStation(const mtc::hmi::ScreenContext& context);

  private:
    QMap<QPair<const void*, int>, QPointer<RestartController>> controllers_;
};

}  // namespace mtc::screens
