#include "cnc_core/program/DatFile.h"

#include <cstdio>

#include "cnc_core/program/AtomicWrite.h"
#include "cnc_core/program/FileText.h"

namespace mtc::core {

namespace {

std::string baseName(const std::string& path) {
    std::size_t slash = path.find_last_of("/\\");
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

/// "%NPG:u:xx:y:zzz" for a file name.
std::string headerOpenLine(const DatFileName& name, bool cycle) {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%s:%X:%02d:%d:%03d", cycle ? "%MAC" : "%NPG",
                  static_cast<unsigned>(name.plant), name.package, name.process, name.number);
    return buffer;
}

/// Fields of "%NPG:u:xx:y:zzz"; false when the line has another shape.
bool headerFields(const std::string& header, DatFileName& out) {
    unsigned plant = 0;
    int package = 0, process = 0, number = 0;
    char kind[4];
    // field widths: scanf's conversion of a number out of range is undefined
    if (std::sscanf(header.c_str(), "%%%3[A-Z]:%7X:%9d:%9d:%9d", kind, &plant, &package, &process,
                    &number) != 5)
        return false;
    out = DatFileName{static_cast<int>(plant), package, process, number};
    return true;
}

void checkNameAgainstHeader(Program& program, const DatFileName& name) {
    DatFileName header;
    if (program.header.empty() || !headerFields(program.header, header)) return;
    if (header.plant == name.plant && header.package == name.package &&
        header.process == name.process && header.number == name.number)
        return;
    program.diagnostics.warning("DAT_NAME_MISMATCH", SourceLocation{program.number, "", 2, 1},
                                "the header (" +
                                    program.header.substr(0, program.header.find('\n')) +
                                    ") does not match the file name " + program.name);
}

}  // namespace

Program DatFile::parse(SourceText text, const std::string& fileName, ParseOptions options) {
    std::optional<DatFileName> name = parseDatFileName(fileName);
    if (options.programNumber == 0 && name) options.programNumber = name->number;
    if (options.name.empty()) options.name = baseName(fileName);
    Program program = parseProgram(std::move(text), options);
    if (name) checkNameAgainstHeader(program, *name);
    return program;
}

Program DatFile::read(const std::string& path, ParseOptions options) {
    std::optional<DatFileName> name = parseDatFileName(path);
    if (options.programNumber == 0 && name) options.programNumber = name->number;
    std::string text, error;
    if (!readFileText(path, text, error)) {
        Program program;
        program.number = options.programNumber;
        program.name = options.name.empty() ? baseName(path) : options.name;
        program.diagnostics.error("FILE_UNREADABLE", SourceLocation{program.number, "", 0, 0},
                                  error);
        return program;
    }
    return parse(std::move(text), path, std::move(options));
}

std::string DatFile::format(const Program& program, const DatFileName& name) {
    if (program.hasDatHeader) return program.source.str();
    std::string fileName = formatDatFileName(name);
    std::string text =
        "iMTc/mtc200-panel/" + std::to_string(program.source.size()) + "/" + fileName + "\n";
    text += headerOpenLine(name, program.isCycle) + "\n";
    text += "*" + (program.title.empty() ? program.name : program.title) + "\n";
    text += program.isCycle ? "%MAC\n" : "%NPG\n";
    text += program.source.view();
    if (!text.empty() && text.back() != '\n') text += '\n';
    bool hasEnd = !program.blocks.empty() && (program.blocks.back().flags & kBlockProgramEnd);
    if (!hasEnd) {
        int next = 0;
        for (std::size_t i = program.blocks.size(); i-- > 0;) {
            std::int32_t number = program.blocks.numberAt(i);
            if (number >= 0) {
                next = number + 1 > 9999 ? 0 : number + 1;
                break;
            }
        }
        char line[32];
        std::snprintf(line, sizeof line, "N%04d PROGRAMMENDE\n", next);
        text += line;
    }
    return text;
}

bool DatFile::write(const std::string& path, const Program& program, const DatFileName& name,
                    DiagnosticList& diagnostics) {
    std::string error;
    if (writeFileAtomically(path, format(program, name), error)) return true;
    diagnostics.error("FILE_WRITE_FAILED", SourceLocation{program.number, "", 0, 0}, error);
    return false;
}

}  // namespace mtc::core
