#include "screens/editor/LineStore.h"

#include <QByteArray>
#include <algorithm>
#include <cstring>

namespace mtc::screens {

namespace {

/// Offsets just after every '\n' of bytes[0, size), shifted by `base`.
void appendLineStarts(const char* bytes, std::size_t size, std::size_t base,
                      std::vector<std::size_t>& starts) {
    const char* at = bytes;
    const char* end = bytes + size;
    while (at < end) {
        const void* found = std::memchr(at, '\n', static_cast<std::size_t>(end - at));
        if (!found) break;
        at = static_cast<const char*>(found) + 1;
        starts.push_back(base + static_cast<std::size_t>(at - bytes));
    }
}

}  // namespace

LineStore::LineStore(std::string text) : text_(std::move(text)) {
    // Room for edits: an insert must not copy the whole text to a new
    // buffer (untouched reserve costs no resident memory).
    text_.reserve(text_.size() + text_.size() / 16 + 65536);
    const auto lines = static_cast<std::size_t>(std::count(text_.begin(), text_.end(), '\n')) + 1;
    starts_.reserve(lines + lines / 16 + 4096);
    appendLineStarts(text_.data(), text_.size(), 0, starts_);
}

std::size_t LineStore::lineEnd(int line) const {
    const auto next = static_cast<std::size_t>(line) + 1;
    return next < starts_.size() ? starts_[next] - 1 : text_.size();
}

QString LineStore::text(int first, int lines) const {
    first = std::clamp(first, 0, count() - 1);
    const int last = std::clamp(first + lines - 1, first, count() - 1);
    const std::size_t begin = starts_[static_cast<std::size_t>(first)];
    const std::size_t end = lineEnd(last);
    return QString::fromUtf8(text_.data() + begin, static_cast<int>(end - begin));
}

void LineStore::replace(int first, int lines, const QString& replacement) {
    first = std::clamp(first, 0, count() - 1);
    const int last = std::clamp(first + lines - 1, first, count() - 1);
    const std::size_t begin = starts_[static_cast<std::size_t>(first)];
    const std::size_t end = lineEnd(last);
    const QByteArray bytes = replacement.toUtf8();
    const auto size = static_cast<std::size_t>(bytes.size());
    text_.replace(begin, end - begin, bytes.constData(), size);

    std::vector<std::size_t> fresh;
    appendLineStarts(bytes.constData(), size, begin, fresh);
    const auto from = starts_.begin() + first + 1;
    const auto oldEnd = starts_.begin() + last + 1;
    const std::size_t shifted = static_cast<std::size_t>(oldEnd - starts_.begin());
    // The lines after the replaced ones move by the change in size.
    for (std::size_t i = shifted; i < starts_.size(); ++i)
        starts_[i] = starts_[i] + size - (end - begin);
    if (static_cast<std::size_t>(oldEnd - from) == fresh.size()) {
        std::copy(fresh.begin(), fresh.end(), from);
        return;
    }
    const auto at = starts_.erase(from, oldEnd);
    starts_.insert(at, fresh.begin(), fresh.end());
}

}  // namespace mtc::screens
