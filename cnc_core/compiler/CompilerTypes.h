#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/machine/MachineConfig.h"

/// Data types of the NC compiler's public API (seed 001). See Compiler.h.
namespace mtc::core {

/// A global macro of the "NC options" (seed 001, ch. 4): valid in all
/// programs and in MDI. Name <= 20 characters, body <= 156 characters.
struct MacroDefinition {
    std::string name;
    std::string body;
};

/// The compiler settings of the NC options plus what the compiler needs
/// from the machine.
struct CompilerOptions {
    bool compilerActive = false;                ///< "Compiler active" (preset: No, seed 001 ch. 7)
    std::vector<MacroDefinition> globalMacros;  ///< "NC options" global macros
    const ProcessConfig* process = nullptr;     ///< axes and parameters; nullptr = X Y Z
    int programNumber = 0;                      ///< goes into every error
    std::string programName;                    ///< file name, for messages
    int maxErrors = 40;                         ///< seed 001 ch. 9: then the compile stops
};

/// One message of the compiler, as it goes into the .ERR file and the
/// error window. Block errors have `block` ("N0053", "N0053:0001"; "L12"
/// for a block without number); general errors have `block` empty and
/// `generalNumber` >= 1 (written A0001).
struct CompilerError {
    Severity severity = Severity::Error;
    std::string code;                  ///< stable code, e.g. COMPILER_CFRD_NO_TARGET
    std::string block;                 ///< block id, "" for general errors
    int generalNumber = 0;             ///< Auuuu number of a general error
    int sourceLine = 0;                ///< 1-based line in the source program (0 = none)
    int program = 0;                   ///< program number
    std::string message;               ///< brief message, <= 52 characters
    std::vector<std::string> details;  ///< additional text, <= 14 lines of <= 65 characters
};

/// What one line of the object file is.
enum class ObjectLineKind : std::uint8_t {
    Identification,  ///< first line, copied from the source
    Header,          ///< %NPG ... %NPG, copied
    Block,           ///< first line of an NC block
    Continuation,    ///< six-blank continuation line of an NC block
    ProgramEnd,      ///< the PROGRAMMENDE line
};

/// Line map of the object file: entry i describes object line i + 1.
struct ObjectLine {
    ObjectLineKind kind = ObjectLineKind::Block;
    std::uint32_t sourceLine = 0;    ///< the source line it stems from (0 = none)
    std::int32_t sourceNumber = -1;  ///< source block number (-1 = none)
    std::int32_t subNumber = 0;      ///< enhanced block number
    bool intermediate = false;       ///< a block the compiler inserted
};

/// Status bit of a program in the program directory (seed 001, ch. 7).
enum class CompileStatus : std::uint8_t {
    NotNeeded,    ///< ' ' the program needs no compilation
    NotCompiled,  ///< 'N'
    Compiled,     ///< 'C'
    Error,        ///< 'E'
};

/// ' ', 'N', 'C' or 'E'.
char statusLetter(CompileStatus status);

/// Result of one compile.
struct CompileResult {
    CompileStatus status = CompileStatus::NotCompiled;  ///< Compiled or Error
    std::string identification;         ///< the source's identification line ("" if none)
    std::string objectText;             ///< the .NCO text; empty when status == Error
    std::vector<CompilerError> errors;  ///< errors and warnings in order found
    std::vector<ObjectLine> lineMap;    ///< per object line
    std::size_t objectBlocks = 0;       ///< NC blocks written (without PROGRAMMENDE)
    /// True when some entry of `errors` is an error (not only warnings).
    bool hasErrors() const;
};

}  // namespace mtc::core
