#pragma once

#include <string>

#include "cnc_core/language/Parser.h"
#include "cnc_core/program/DatFileName.h"

namespace mtc::core {

/// Reading and writing NC program files in the seed format (seed 001,
/// ch. 10/11; seed 000, 7.2): identification line, %NPG (or %MAC) header,
/// blocks, PROGRAMMENDE. Loose files of blocks are read too.
class DatFile {
  public:
    /// Reads and parses the file at `path`. Never throws and never drops
    /// text: a file with errors loads with diagnostics; an unreadable file
    /// gives a Program with no blocks and a FILE_UNREADABLE error. When
    /// `options.programNumber` is 0 and the file name follows NuxxYzzz.DAT,
    /// the number comes from the name; the name defaults to the file name.
    /// A name that disagrees with the %NPG header adds DAT_NAME_MISMATCH.
    static Program read(const std::string& path, ParseOptions options = {});

    /// Parses `text` as the content of a file called `fileName` (same rules
    /// as read(), without the file system).
    static Program parse(SourceText text, const std::string& fileName, ParseOptions options = {});

    /// The file text for `program`: a program read from a .DAT file is
    /// written back exactly as read (round trip); a loose program gets an
    /// identification line, a %NPG header built from `name` and a final
    /// PROGRAMMENDE block.
    static std::string format(const Program& program, const DatFileName& name);

    /// Writes format(program, name) to `path` atomically (temporary file in
    /// the same directory + fsync + rename). Returns false with a
    /// FILE_WRITE_FAILED diagnostic in `diagnostics` when it cannot; the old
    /// file is then unchanged.
    static bool write(const std::string& path, const Program& program, const DatFileName& name,
                      DiagnosticList& diagnostics);
};

}  // namespace mtc::core
