#pragma once

#include <QString>
#include <memory>

#include "hmi/PanelOptions.h"

namespace mtc::hmi {

class CellSession;
class PanelWindow;
class ScreenRegistry;

/// Builds the cell the options ask for: machine configuration (file or the
/// built-in demo cell) and programs (directory or the built-in demo
/// programs). Returns nullptr and a readable `error` when a file is bad.
std::unique_ptr<CellSession> createSession(const PanelOptions& options, QString& error);

/// Applies --process, --program and --screen to a freshly built window.
/// Returns false with `error` for an unknown screen, process or program.
bool applyStartOptions(const PanelOptions& options, CellSession& session, PanelWindow& window,
                       QString& error);

}  // namespace mtc::hmi
