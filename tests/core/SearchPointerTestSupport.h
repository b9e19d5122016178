#pragma once

// Programs and a store for the search pointer tests (restart screen,
// seed 000 ch. 2.3-2.6). The programs are our own; they use every jump and
// call kind of seed 000, 2.5 once.

#include <map>
#include <memory>
#include <string>

#include "cnc_core/language/Parser.h"
#include "cnc_core/program/ProgramStore.h"
#include "cnc_core/restart/SearchPointer.h"

namespace mtc::core::testing {

/// Main program 5 of process 0: one block per jump/call kind.
inline const char* kSearchMain =
    "N0000 (SEARCH POINTER MAIN)\n"
    "N0001 : G0 G90 G54 X0 Y0 Z50 ;first primary block\n"
    "N0002 T1 BSR .TOOL ;tool change in program 99\n"
    "N0003 @20=3\n"
    "N0004 .LOOP G1 X10 F500 ;loop start\n"
    "N0005 BSR .SIDE ;local subroutine\n"
    "N0006 @20=@20-1 BNE .LOOP\n"
    "N0007 : G0 Z20 ;second primary block\n"
    "N0008 JSR 6\n"
    "N0009 JSR @30 ;program by variable\n"
    "N0010 BES .SKIP 0:5\n"
    "N0011 JEV 6 0:7\n"
    "N0012 .SKIP BEV .TOOL 0:8\n"
    "N0013 BSR .*PECK ;drilling cycle\n"
    "N0014 BRA .NOWHERE\n"
    "N0015 JMP 7\n"
    "N0016 JMP @31\n"
    "N0017 JSR @1:40 ;variable of process 1\n"
    "N0018 BST\n"
    "N0019 M30\n"
    "; local subroutine, comment line with the word hidden-gem\n"
    "N0020 .SIDE G1 Y10 ;side wall\n"
    "N0021 Y0 RTS\n"
    "N0022 PROGRAMMENDE\n";

/// Program 99 of process 0: label library with a recursive subroutine.
inline const char* kSearchLibrary =
    "N0000 (LIBRARY)\n"
    "N0001 M30\n"
    "N0002 .TOOL M6 RTS\n"
    "N0003 .DEEP G1 X1 BSR .DEEP ;recursion for the level limit\n"
    "N0004 BRA .DEEP ;branch: no new program level\n"
    "N0005 RTS\n"
    "N0006 PROGRAMMENDE\n";

inline const char* kSearchSub6 =
    "N0000 (SUBPROGRAM 6)\n"
    "N0001 : G1 X5 F100\n"
    "N0002 RTS\n"
    "N0003 PROGRAMMENDE\n";

/// Program 7: primary blocks after G91 / G51 (seed 000, 5.1 note).
inline const char* kSearchIncremental =
    "N0000 G90 X0\n"
    "N0001 : X1 ;G91 below, comment mentions G91 too\n"
    "N0002 G91 X5\n"
    "N0003 : X5\n"
    "N0004 G90 X0\n"
    "N0005 : X2\n"
    "N0006 G51 X1\n"
    "N0007 : X3\n"
    "N0008 X4\n";

/// Program 8: a subroutine at the start of the program (seed 000, 2.4).
inline const char* kSearchSubFirst =
    "N0000 .EDGE G1 X1 F200\n"
    "N0001 Y1 RTS\n"
    "N0002 .MAIN : G0 X0 Y0\n"
    "N0003 BSR .EDGE\n"
    "N0004 G0 X9\n"
    "N0005 M30\n";

inline const char* kSearchCycle =
    "N0000 .*PECK G1 Z-5 F100\n"
    "N0001 G0 Z2 RTS\n";

inline ProgramPtr parsed(const std::string& text, int number) {
    ParseOptions options;
    options.programNumber = number;
    return std::make_shared<Program>(parseProgram(text, options));
}

/// The store of the tests: programs 5, 6, 7, 8, 99 of process 0, program 6
/// of process 1, and the cycle PECK.
struct SearchStore {
    ProgramStore store;
    std::map<std::pair<int, int>, double> variables{{{0, 30}, 6.0}, {{1, 40}, 6.0}};
    std::map<std::pair<int, int>, bool> events{{{0, 8}, true}};

    SearchStore() {
        store.put(0, 5, parsed(kSearchMain, 5));
        store.put(0, 6, parsed(kSearchSub6, 6));
        store.put(0, 7, parsed(kSearchIncremental, 7));
        store.put(0, 8, parsed(kSearchSubFirst, 8));
        store.put(0, 99, parsed(kSearchLibrary, 99));
        store.put(1, 6, parsed(kSearchSub6, 6));
        auto cycle = std::make_shared<Program>(parseProgram(kSearchCycle, {}));
        cycle->isCycle = true;
        store.putCycle("PECK", cycle);
    }

    SearchSources sources() {
        SearchSources s;
        s.readVariable = [this](int process, int index, double& value) {
            auto it = variables.find({process, index});
            if (it == variables.end()) return false;
            value = it->second;
            return true;
        };
        s.readEvent = [this](int process, int event) {
            auto it = events.find({process, event});
            return it != events.end() && it->second;
        };
        return s;
    }
};

/// Block index of block number `n` in the displayed program.
inline std::uint32_t blockOf(const SearchPointer& pointer, int n) {
    const Program& p = *pointer.current().program;
    for (std::uint32_t i = 0; i < p.blocks.size(); ++i)
        if (p.blocks[i].number == n) return i;
    return UINT32_MAX;
}

/// "P5 N0012" of the cursor.
inline std::string cursorText(const SearchPointer& pointer) {
    const SearchLevel& level = pointer.current();
    return "P" + std::to_string(level.program->number) + " " + level.program->blockId(level.cursor);
}

}  // namespace mtc::core::testing
