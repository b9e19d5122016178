#include "cnc_core/program/DatFileName.h"

#include <cstdio>

namespace mtc::core {

namespace {

bool inRange(const DatFileName& n) {
    return n.plant >= 0 && n.plant <= 15 && n.package >= 1 && n.package <= 99 && n.process >= 0 &&
           n.process <= 6 && n.number >= 1 && n.number <= 99;
}

int digit(char c) {
    return c >= '0' && c <= '9' ? c - '0' : -1;
}

int hexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

bool fail(std::string* whyNot, const char* reason) {
    if (whyNot) *whyNot = reason;
    return false;
}

bool parseFields(std::string_view name, DatFileName& out, std::string* whyNot) {
    if (name.size() != 12 || (name[0] != 'N' && name[0] != 'n'))
        return fail(whyNot, "program file names have the form NuxxYzzz.DAT");
    std::string_view ext = name.substr(8);
    if (ext != ".DAT" && ext != ".dat" && ext != ".Dat")
        return fail(whyNot, "program file names end in .DAT");
    out.plant = hexDigit(name[1]);
    int d[6];
    for (int i = 0; i < 6; ++i) {
        d[i] = digit(name[2 + static_cast<std::size_t>(i)]);
        if (d[i] < 0) return fail(whyNot, "package, process and program number must be digits");
    }
    if (out.plant < 0) return fail(whyNot, "the plant address is one digit 0-9 or A-F");
    out.package = d[0] * 10 + d[1];
    out.process = d[2];
    out.number = d[3] * 100 + d[4] * 10 + d[5];
    if (out.package < 1) return fail(whyNot, "package number must be 01..99");
    if (out.process > 6) return fail(whyNot, "process number must be 0..6");
    if (out.number < 1 || out.number > 99) return fail(whyNot, "program number must be 001..099");
    return true;
}

}  // namespace

std::optional<DatFileName> parseDatFileName(std::string_view path, std::string* whyNot) {
    std::size_t slash = path.find_last_of("/\\");
    std::string_view name = slash == std::string_view::npos ? path : path.substr(slash + 1);
    DatFileName result;
    if (!parseFields(name, result, whyNot)) return std::nullopt;
    return result;
}

std::string formatDatFileName(const DatFileName& name) {
    if (!inRange(name)) return {};
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "N%X%02d%d%03d.DAT", static_cast<unsigned>(name.plant),
                  name.package, name.process, name.number);
    return buffer;
}

}  // namespace mtc::core
