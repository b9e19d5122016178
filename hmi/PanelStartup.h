#pragma once

#include <QString>
#include <memory>

#include "hmi/PanelOptions.h"

namespace mtc::hmi {

class CellSession;
class PanelWindow;
class ScreenRegistry;

/// Puts the C library's number format (LC_NUMERIC) back to "C" after
/// QApplication took the desk's locale for everything (D-013): the core's
/// files and NC text always use '.', whatever the desk's language. The
/// texts, dates and collation keep the desk's locale. createSession() calls
/// it, so the panel and every GUI test built on a session use it.
void useCNumberFormat();

/// Builds the cell the options ask for: machine configuration (file or the
/// built-in demo cell) and programs (directory or the built-in demo
/// programs). Returns nullptr and a readable `error` when a file is bad.
std::unique_ptr<CellSession> createSession(const PanelOptions& options, QString& error);

/// Applies --process, --program and --screen to a freshly built window.
/// Returns false with `error` for an unknown screen, process or program.
bool applyStartOptions(const PanelOptions& options, CellSession& session, PanelWindow& window,
                       QString& error);

}  // namespace mtc::hmi
