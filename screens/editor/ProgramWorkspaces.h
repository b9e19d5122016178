#pragma once

#include <QMap>
#include <QPair>
#include <memory>

#include "hmi/Screen.h"

namespace mtc::hmi {
class ProgramWorkspace;
}

namespace mtc::screens {

/// Hands the program directory, editor, error window and runtime view of a
/// station the same ProgramWorkspace (compile status, error log, the
/// program the editor shows). The screens own it together.
class ProgramWorkspaces {
  public:
    /// The workspace of the context's station; created on first use.
    std::shared_ptr<mtc::hmi::ProgramWorkspace> forStation(const mtc::hmi::ScreenContext& context);

  private:
    QMap<QPair<const void*, int>, std::weak_ptr<mtc::hmi::ProgramWorkspace>> workspaces_;
};

}  // namespace mtc::screens
