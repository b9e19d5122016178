#include "cnc_core/program/FileText.h"

#include <cstdio>
#include <filesystem>

namespace mtc::core {

bool readFileText(const std::string& path, std::string& text, std::string& error) {
    text.clear();
    std::error_code code;
    if (!std::filesystem::is_regular_file(path, code)) {
        error = "not a readable file: " + path;
        return false;
    }
    std::uintmax_t size = std::filesystem::file_size(path, code);
    std::FILE* file = code ? nullptr : std::fopen(path.c_str(), "rb");
    if (file == nullptr) {
        error = "cannot open " + path;
        return false;
    }
    text.resize(static_cast<std::size_t>(size));
    std::size_t read = size ? std::fread(text.data(), 1, text.size(), file) : 0;
    // A file that grew while reading: take the rest too.
    char chunk[4096];
    for (std::size_t more; (more = std::fread(chunk, 1, sizeof chunk, file)) > 0;) {
        text.resize(read);
        text.append(chunk, more);
        read = text.size();
    }
    bool failed = std::ferror(file) != 0;
    std::fclose(file);
    text.resize(read);
    if (failed) {
        text.clear();
        error = "cannot read " + path;
        return false;
    }
    return true;
}

}  // namespace mtc::core
