#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>

#include "cnc_core/language/Diagnostic.h"

namespace mtc::core {

/// What a station was doing when a diagnostic arose.
enum class DiagnosticSource {
    Run,      ///< an automatic run: the interpreter, or Start refused before it
    Mdi,      ///< manual data input: the check of the entry or its run
    Restart,  ///< the NC program restart: acceptance, computing process, ADJUST / REPOS
};

/// One diagnostic of a station, numbered in the order it arose.
struct LoggedDiagnostic {
    std::uint64_t serial = 0;  ///< 1, 2, ... (never reused)
    DiagnosticSource source = DiagnosticSource::Run;
    Diagnostic diagnostic;
};

/// The station's diagnostics as data, for the error window and anyone else
/// who wants them: the records stay structured (code, program, block, line,
/// details) all the way, nobody formats them into text and parses them back.
/// Bounded: the oldest records go first once kCapacity are kept, so a
/// program that warns in every block of an endless loop cannot grow it.
class DiagnosticLog {
  public:
    static constexpr std::size_t kCapacity = 1000;

    void add(DiagnosticSource source, const Diagnostic& diagnostic);
    void addAll(DiagnosticSource source, const DiagnosticList& diagnostics);
    /// Serial of the newest record (0 = none yet): readers remember it and
    /// ask for what came after.
    std::uint64_t lastSerial() const { return serial_; }
    /// Calls `visit(const LoggedDiagnostic&)` for every kept record newer
    /// than `after`, oldest first.
    template <typename Visit>
    void forEachAfter(std::uint64_t after, Visit visit) const {
        for (const LoggedDiagnostic& record : records_)
            if (record.serial > after) visit(record);
    }
    std::size_t size() const { return records_.size(); }

  private:
    std::deque<LoggedDiagnostic> records_;
    std::uint64_t serial_ = 0;
};

}  // namespace mtc::core
