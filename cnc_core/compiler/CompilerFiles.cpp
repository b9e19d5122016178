#include "cnc_core/compiler/CompilerFiles.h"

#include <cstdio>
#include <cstdlib>
#include <ctime>

#include "cnc_core/compiler/CompilerText.h"
#include "cnc_core/program/AtomicWrite.h"

namespace mtc::core {

namespace {

std::vector<std::string> splitFields(const std::string& text, char separator) {
    std::vector<std::string> fields(1);
    for (char c : text) {
        if (c == separator)
            fields.emplace_back();
        else
            fields.back() += c;
    }
    return fields;
}

std::string withExtension(const std::string& path, const char* extension) {
    const std::size_t slash = path.find_last_of('/');
    const std::size_t dot = path.find_last_of('.');
    const std::string stem = dot != std::string::npos && (slash == std::string::npos || dot > slash)
                                 ? path.substr(0, dot)
                                 : path;
    return stem + extension;
}

std::string baseName(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

/// `body` with its identification line (the first line) updated.
std::string stamped(const std::string& identification, const std::string& body,
                    const std::string& fileName) {
    if (identification.empty()) return body;
    return updatedIdentification(identification, fileName, body.size(), currentStamp()) + "\n" +
           body;
}

}  // namespace

std::string formatErrorFile(const std::string& identification,
                            const std::vector<CompilerError>& errors) {
    std::string text = identification + "\n";
    for (const CompilerError& e : errors) {
        const std::vector<std::string> details = limitDetails(e.details);
        if (e.block.empty() && e.generalNumber > 0)
            text += "A" + formatFourDigits(e.generalNumber);
        else if (e.block.empty())
            text += "L" + formatFourDigits(e.sourceLine);
        else
            text += e.block.substr(0, 5);  // Nxxxx: the source block
        text += e.severity == Severity::Error ? ":$W:" : ":$I:";
        text += formatFourDigits(static_cast<int>(details.size())) + "\n";
        text += limitMessage(e.message) + "\n";
        for (const std::string& line : details)
            text += line + "\n";
    }
    return text;
}

std::vector<CompilerError> parseErrorFile(const std::string& text, std::string& identification) {
    std::vector<std::string> lines = splitFields(text, '\n');
    for (std::string& line : lines)
        if (!line.empty() && line.back() == '\r') line.pop_back();
    std::vector<CompilerError> errors;
    identification = lines.empty() ? std::string() : lines[0];
    for (std::size_t i = 1; i < lines.size(); ++i) {
        const std::string& line = lines[i];
        if (line.size() != 13 || line[5] != ':' || line[6] != '$' || line[8] != ':') continue;
        CompilerError e;
        e.severity = line[7] == 'I' ? Severity::Warning : Severity::Error;
        const int number = std::atoi(line.substr(1, 4).c_str());
        if (line[0] == 'A')
            e.generalNumber = number;
        else if (line[0] == 'N')
            e.block = line.substr(0, 5);
        else
            e.sourceLine = number;
        const std::size_t count = static_cast<std::size_t>(std::atoi(line.substr(9).c_str()));
        if (i + 1 < lines.size()) e.message = lines[++i];
        for (std::size_t k = 0; k < count && i + 1 < lines.size(); ++k)
            e.details.push_back(lines[++i]);
        errors.push_back(std::move(e));
    }
    return errors;
}

bool errorFileHasErrors(const std::string& text) {
    std::string identification;
    for (const CompilerError& e : parseErrorFile(text, identification))
        if (e.severity == Severity::Error) return true;
    return false;
}

std::string updatedIdentification(const std::string& identification, const std::string& fileName,
                                  std::size_t restBytes, const std::string& stamp) {
    std::vector<std::string> fields = splitFields(identification, '/');
    if (fields.size() != 8 || fields[0] != "iMTc" || fields[3].size() != 10) return identification;
    const std::size_t space = stamp.find(' ');
    fields[4] = stamp.substr(0, space);
    fields[5] = space == std::string::npos ? fields[5] : stamp.substr(space + 1);
    fields[6] = fileName;
    std::string line;
    for (int pass = 0; pass < 2; ++pass) {  // the size includes this line itself
        line.clear();
        for (std::size_t i = 0; i < fields.size(); ++i)
            line += (i ? "/" : "") + fields[i];
        char size[16];
        std::snprintf(size, sizeof size, "%010zu", line.size() + 1 + restBytes);
        fields[3] = size;
    }
    line.clear();
    for (std::size_t i = 0; i < fields.size(); ++i)
        line += (i ? "/" : "") + fields[i];
    return line;
}

std::string currentStamp() {
    std::time_t now = std::time(nullptr);
    if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH"))
        now = static_cast<std::time_t>(std::strtoll(epoch, nullptr, 10));
    std::tm tm{};
    gmtime_r(&now, &tm);
    char buffer[32];
    std::strftime(buffer, sizeof buffer, "%d.%m.%Y %H:%M:%S", &tm);
    return buffer;
}

bool writeCompileFiles(const std::string& sourcePath, const std::string& objectPath,
                       const CompileResult& result, std::string& errorPath, std::string& error) {
    const std::string object = objectPath.empty() ? withExtension(sourcePath, ".NCO") : objectPath;
    errorPath = withExtension(object, ".ERR");
    const std::string* outputs[] = {&object, &errorPath};
    for (const std::string* output : outputs)
        if (sameFile(*output, sourcePath)) {
            error = *output + " is the source program itself; it is not overwritten (name "
                              "another output file)";
            return false;
        }
    if (object == errorPath || sameFile(object, errorPath)) {
        error = object + " would be both the object file and the error file";
        return false;
    }
    if (!checkReplaceable(object, error) || !checkReplaceable(errorPath, error)) return false;
    // CF-013: the file that would not belong to the new result goes first
    // (the old .ERR before a new object file, the old object file before new
    // errors), then the new file. A kill at any moment leaves the old pair,
    // one old file alone or the new file: never an object file beside the
    // errors of another compile.
    if (result.status == CompileStatus::Compiled) {
        std::string body = result.objectText;
        if (!result.identification.empty() &&
            body.compare(0, result.identification.size() + 1, result.identification + "\n") == 0)
            body = stamped(result.identification, body.substr(result.identification.size() + 1),
                           baseName(object));
        if (!removeFile(errorPath, error) || !writeFileAtomically(object, body, error))
            return false;
    } else if (!removeFile(object, error)) {  // errors: no object file (seed 001 ch. 11)
        return false;
    }
    // C-004 / C-014: the error file exists only when there are errors (seed
    // 001 ch. 9); warnings go with the compile result, not into a file.
    if (!result.hasErrors()) {
        errorPath.clear();
        return true;
    }
    const std::string body =
        formatErrorFile("", result.errors).substr(1);  // without the empty first line
    const std::string text = result.identification.empty()
                                 ? "\n" + body
                                 : stamped(result.identification, body, baseName(errorPath));
    return writeFileAtomically(errorPath, text, error);
}

}  // namespace mtc::core
