#include "resources/EmbeddedResources.h"

#include <algorithm>

namespace mtc::resources {
namespace detail {
extern const EmbeddedFile files[];
}

std::string_view find(std::string_view name, bool* found) {
    for (const EmbeddedFile* f = detail::files; f->name != nullptr; ++f) {
        if (name == f->name) {
            if (found) *found = true;
            return {reinterpret_cast<const char*>(f->data), f->size};
        }
    }
    if (found) *found = false;
    return {};
}

std::vector<std::string> list(std::string_view prefix) {
    std::vector<std::string> names;
    for (const EmbeddedFile* f = detail::files; f->name != nullptr; ++f) {
        std::string_view name(f->name);
        if (name.substr(0, prefix.size()) == prefix) names.emplace_back(name);
    }
    std::sort(names.begin(), names.end());
    return names;
}

std::vector<std::pair<std::string, std::string>> demoPrograms() {
    std::vector<std::pair<std::string, std::string>> files;
    for (const std::string& name : list("programs/"))
        files.emplace_back(name, std::string(find(name)));
    return files;
}

}  // namespace mtc::resources
