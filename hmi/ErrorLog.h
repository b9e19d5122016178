#pragma once

#include <QObject>
#include <QString>
#include <QStringList>
#include <QVector>

#include "cnc_core/language/Diagnostic.h"

namespace mtc::hmi {

/// Where an entry of the error window comes from (seed 001, ch. 9: the
/// compilers; the panel adds the interpreter, the restart computing process
/// and manual data input, docs/decisions/mdi.md).
enum class ErrorOrigin { Compiler, Runtime, Restart, Mdi };

/// "compiler", "runtime", "restart", "MDI".
QString originName(ErrorOrigin origin);

/// One message of the error window: brief message, additional text and the
/// place in the NC program it belongs to.
struct ErrorEntry {
    ErrorOrigin origin = ErrorOrigin::Compiler;
    bool warning = false;
    int program = 0;      ///< program number (0 = none)
    QString block;        ///< "N0030", "N0030:0001", "A0001" (general) or ""
    int line = 0;         ///< 1-based source line (0 = unknown)
    QString code;         ///< stable code (COMPILER_..., interpreter codes)
    QString message;      ///< brief message
    QStringList details;  ///< additional text
};

/// The entry of a diagnostic (code, program, block, line), with `origin`.
/// Its brief message and additional text are in the panel's language
/// (installedCoreLanguage(), docs/DECISIONS.md D-023): in German the core's
/// table gives the brief message and the core's English message, which
/// names the values, opens the additional text.
ErrorEntry entryFromDiagnostic(const mtc::core::Diagnostic& diagnostic, ErrorOrigin origin);

/// Sets the brief message and additional text of `entry` from `diagnostic`
/// in the panel's language (as entryFromDiagnostic() does).
void setEntryText(ErrorEntry& entry, const mtc::core::Diagnostic& diagnostic);

/// The errors of one station for the error window, newest source last:
/// the compiler's errors per program (replaced by every compile of that
/// program), runtime errors of the interpreter and errors of the restart
/// computing process. A plain model: screens read it, owners fill it.
class ErrorLog : public QObject {
    Q_OBJECT
  public:
    explicit ErrorLog(QObject* parent = nullptr) : QObject(parent) {}

    /// Replaces the compiler entries of `program` with `entries`.
    void setCompilerErrors(int program, const QVector<ErrorEntry>& entries);
    /// Appends a runtime or restart entry; an entry equal to the last one of
    /// the same origin is not repeated. At most kMaxEntries are kept per origin.
    void add(const ErrorEntry& entry);
    /// Appends several entries as add() does, with one changed() signal.
    void addAll(const QVector<ErrorEntry>& entries);
    /// Removes every entry of `origin`.
    void clear(ErrorOrigin origin);
    const QVector<ErrorEntry>& entries() const { return entries_; }
    /// Entries of `origin` (in order).
    int count(ErrorOrigin origin) const;

    static constexpr int kMaxEntries = 200;

  signals:
    void changed();

  private:
    /// add() without the signal; false when the entry repeats the last one.
    bool append(const ErrorEntry& entry);

    QVector<ErrorEntry> entries_;
};

}  // namespace mtc::hmi
