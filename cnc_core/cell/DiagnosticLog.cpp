#include "cnc_core/cell/DiagnosticLog.h"

namespace mtc::core {

void DiagnosticLog::add(DiagnosticSource source, const Diagnostic& diagnostic) {
    records_.push_back({++serial_, source, diagnostic});
    if (records_.size() > kCapacity) records_.pop_front();
}

void DiagnosticLog::addAll(DiagnosticSource source, const DiagnosticList& diagnostics) {
    for (const Diagnostic& d : diagnostics.items())
        add(source, d);
}

}  // namespace mtc::core
