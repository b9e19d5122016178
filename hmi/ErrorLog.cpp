#include "hmi/ErrorLog.h"

namespace mtc::hmi {

QString originName(ErrorOrigin origin) {
    switch (origin) {
        case ErrorOrigin::Compiler:
            return "compiler";
        case ErrorOrigin::Runtime:
            return "runtime";
        case ErrorOrigin::Restart:
            return "restart";
        case ErrorOrigin::Mdi:
            return "MDI";
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

void ErrorLog::add(const ErrorEntry& entry) {
    for (int i = entries_.size() - 1; i >= 0; --i) {
        if (entries_[i].origin != entry.origin) continue;
        if (sameMessage(entries_[i], entry)) return;
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
    emit changed();
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
