#include "hmi/ErrorLog.h"

#include "hmi/PanelLanguage.h"

namespace mtc::hmi {

QString originName(ErrorOrigin origin) {
    switch (origin) {
        case ErrorOrigin::Compiler:
            return ErrorLog::tr("compiler");
        case ErrorOrigin::Runtime:
            return ErrorLog::tr("runtime");
        case ErrorOrigin::Restart:
            return ErrorLog::tr("restart");
        case ErrorOrigin::Mdi:
            return ErrorLog::tr("MDI");
    }
    return "?";
}

namespace {
bool sameMessage(const ErrorEntry& a, const ErrorEntry& b) {
    return a.origin == b.origin && a.program == b.program && a.block == b.block &&
           a.message == b.message && a.code == b.code;
}
}  // namespace

void ErrorLog::setCompilerErrors(int program, const QVector<ErrorEntry>& entries) {
    QVector<ErrorEntry> kept;
    for (const ErrorEntry& e : entries_)
        if (!(e.origin == ErrorOrigin::Compiler && e.program == program)) kept.push_back(e);
    // Compiler entries stay ahead of runtime and restart entries.
    int insertAt = 0;
    while (insertAt < kept.size() && kept[insertAt].origin == ErrorOrigin::Compiler)
        ++insertAt;
    for (int i = 0; i < entries.size(); ++i) {
        ErrorEntry e = entries[i];
        e.origin = ErrorOrigin::Compiler;
        e.program = program;
        kept.insert(insertAt + i, e);
    }
    entries_ = kept;
    emit changed();
}

ErrorEntry entryFromDiagnostic(const mtc::core::Diagnostic& d, ErrorOrigin origin) {
    ErrorEntry entry;
    entry.origin = origin;
    entry.warning = d.severity == mtc::core::Severity::Warning;
    entry.program = d.where.program;
    entry.block = QString::fromStdString(d.where.block);
    entry.line = d.where.line;
    setEntryText(entry, d);
    return entry;
}

void setEntryText(ErrorEntry& entry, const mtc::core::Diagnostic& diagnostic) {
    const mtc::core::DiagnosticText text =
        mtc::core::diagnosticText(diagnostic, installedCoreLanguage());
    entry.code = QString::fromStdString(diagnostic.code);
    entry.message = QString::fromStdString(text.brief);
    entry.details.clear();
    for (const std::string& line : text.additional)
        entry.details << QString::fromStdString(line);
}

void ErrorLog::add(const ErrorEntry& entry) {
    if (append(entry)) emit changed();
}

void ErrorLog::addAll(const QVector<ErrorEntry>& entries) {
    bool added = false;
    for (const ErrorEntry& entry : entries)
        added = append(entry) || added;
    if (added) emit changed();
}

bool ErrorLog::append(const ErrorEntry& entry) {
    for (int i = entries_.size() - 1; i >= 0; --i) {
        if (entries_[i].origin != entry.origin) continue;
        if (sameMessage(entries_[i], entry)) return false;
        break;
    }
    entries_.push_back(entry);
    if (count(entry.origin) > kMaxEntries) {
        for (int i = 0; i < entries_.size(); ++i)
            if (entries_[i].origin == entry.origin) {
                entries_.remove(i);
                break;
            }
    }
    return true;
}

void ErrorLog::clear(ErrorOrigin origin) {
    const int before = entries_.size();
    QVector<ErrorEntry> kept;
    for (const ErrorEntry& e : entries_)
        if (e.origin != origin) kept.push_back(e);
    entries_ = kept;
    if (entries_.size() != before) emit changed();
}

int ErrorLog::count(ErrorOrigin origin) const {
    int n = 0;
    for (const ErrorEntry& e : entries_)
        if (e.origin == origin) ++n;
    return n;
}

}  // namespace mtc::hmi
