#pragma once

#include <string>
#include <vector>

#include "cnc_core/compiler/CompilerTypes.h"

/// Files of the NC compiler (seed 001, ch. 9 and 11): the .ERR error file,
/// the identification line update, and writing .NCO/.ERR atomically.
namespace mtc::core {

/// Text of an .ERR file: `identification` as the first line, then per
/// message "Nxxxx:$W:yyyy" (block errors; "Auuuu:$W:yyyy" general errors),
/// the brief message and yyyy lines of additional text, without gaps.
/// Warnings are written with "$I" instead of "$W" (decisions/compiler.md).
std::string formatErrorFile(const std::string& identification,
                            const std::vector<CompilerError>& errors);

/// Reads an .ERR text back (for the error window); lines it cannot read
/// are skipped. `identification` gets the first line.
std::vector<CompilerError> parseErrorFile(const std::string& text, std::string& identification);

/// The identification line updated for `fileName` as the user interface does
/// after a compile: in "iMTc/a/b/size/date/time/name/n" the size (10 digits,
/// bytes of the whole file incl. this line), date, time and file name are
/// replaced; any other identification is returned unchanged.
/// `stamp` is "dd.mm.yyyy hh:mm:ss".
std::string updatedIdentification(const std::string& identification, const std::string& fileName,
                                  std::size_t restBytes, const std::string& stamp);

/// "dd.mm.yyyy hh:mm:ss" of now (UTC), or of SOURCE_DATE_EPOCH when that
/// environment variable is set (reproducible files for tests).
std::string currentStamp();

/// True when the text of an error file holds at least one error ($W); an
/// error file with notices ($I) only does not make a program status E.
bool errorFileHasErrors(const std::string& text);

/// Writes the result of a compile of `sourcePath` (a .DAT file): on success
/// the object file `objectPath` (default: .NCO next to the source) and no
/// .ERR (an old one is removed; warnings stay in the result, decision
/// C-014); on errors only the .ERR file (warnings included), and an old
/// object file is removed (seed 001 ch. 9, 11). Atomic writes. Returns false
/// with `error` set when a file cannot be written.
bool writeCompileFiles(const std::string& sourcePath, const std::string& objectPath,
                       const CompileResult& result, std::string& errorPath, std::string& error);

}  // namespace mtc::core
