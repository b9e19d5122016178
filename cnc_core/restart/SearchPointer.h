#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cnc_core/language/Diagnostic.h"
#include "cnc_core/language/Program.h"
#include "cnc_core/program/ProgramStore.h"
#include "cnc_core/restart/ProgramScan.h"
#include "cnc_core/restart/RestartSelection.h"
#include "cnc_core/restart/StartBlockSearch.h"

namespace mtc::core {

/// Where the values shown in the Plane+ windows come from: the variables of
/// the processes and the events of the cell, as they are now. Empty
/// functions read "not available" (variables) and "not set" (events).
struct SearchSources {
    /// Reads @process:index; false when there is no such variable.
    std::function<bool(int process, int index, double& value)> readVariable;
    /// State of event process:event.
    std::function<bool(int process, int event)> readEvent;
};

/// One program level of the search. Level 0 is the selected program; each
/// <Plane+> opens the next level, <Plane-> closes it (seed 000, 2.5).
struct SearchLevel {
    ProgramPtr program;
    /// Block under the cursor. On outer levels: the block whose jump or call
    /// <Plane+> followed (the calling point <Plane-> returns to).
    std::uint32_t cursor = 0;
    /// Block the level was entered at (label block, N0000 of a program).
    std::uint32_t entry = 0;
    JumpKind via = JumpKind::BRA;  ///< command that opened the level (level > 0)
    bool call = false;             ///< opened by BSR, JSR, BEV or JEV
};

/// The window <Plane+> opens before it follows BES/BER/BEV/JEV (the event
/// may be changed) or JMP/JSR/JEV with a variable program number (the value
/// may be changed). Kind::None = no window open.
struct PlaneWindow {
    enum class Kind { None, Event, Variable };
    Kind kind = Kind::None;
    JumpKind jump = JumpKind::BRA;
    EventRef event;           ///< Event: the event of the command
    bool eventSet = false;    ///< Event: its state as shown (current or changed)
    int variableProcess = 0;  ///< Variable: @p:n process
    int variable = 0;         ///< Variable: n
    double value = 0.0;       ///< Variable: value as shown
    bool valueKnown = false;  ///< Variable: the process could read it
    bool writable = true;     ///< Variable: own process (a change can be recorded)
};

/// Answer to one operator action: `ok` = done; otherwise refused and
/// nothing changed. `note` carries the message for the screen (an error when
/// refused, a warning or information when done).
struct SearchReply {
    bool ok = true;
    std::optional<Diagnostic> note;
};

/// Where the computing process starts (seed 000, 2.4).
struct StartBlock {
    int level = 0;         ///< program level of the start block (0 = outermost)
    BlockRef block;        ///< program and block index
    bool primary = false;  ///< the last primary block before the target
};

/// A jump or call command as <Plane+> reads it from the cursor block.
struct SearchJump {
    JumpKind kind = JumpKind::BRA;
    std::uint32_t block = 0;  ///< block of the command (cursor block)
    std::string label;        ///< label without '.' (label jumps and calls)
    int program = 0;          ///< JSR/JMP/JEV with a constant program number
    bool byVariable = false;  ///< JSR/JMP/JEV @n or @p:n
    int variableProcess = 0;
    int variable = 0;
    bool hasEvent = false;  ///< BES/BER/BEV/JEV
    EventRef event;
};

/// Result of <Enter>: a validated selection, or the reason why not.
struct AcceptResult {
    bool ok = false;
    RestartSelection selection;
    StartBlock start;
    DiagnosticList diagnostics;  ///< the error (when !ok) and warnings
};

/// The operator's selection on the NC program restart screen (seed 000,
/// 2.3-2.6): a cursor in the displayed program, <Plane+>/<Plane-> through
/// jumps and calls up to the 10th level, search string, start block, number
/// of runs. Produces a validated RestartSelection. Every key is O(1) or
/// O(log n) in the program size, except the text search (one pass over the
/// source) and the first use of the primary-block index. Plain C++, no Qt.
class SearchPointer {
  public:
    /// `store` must outlive the pointer; `process` is the process number.
    SearchPointer(const ProgramStore& store, int process, SearchSources sources = {});

    /// Entry into the restart screen with the selected program `number`:
    /// one level, cursor on N0000, number of runs 1, start at the program
    /// start, no changed variables or events. Fails (state as before) when
    /// the program does not exist, is empty or is a cycle.
    SearchReply begin(int number);
    bool active() const { return !levels_.empty(); }

    // ---- cursor (seed 000, 2.3); each closes an open Plane+ window
    /// One block up; stops at N0000.
    void up();
    /// One block down; stops at the <End> block.
    void down();
    /// `rows` blocks up (a screen page), clamped to N0000.
    void pageUp(std::uint32_t rows);
    /// `rows` blocks down (a screen page), clamped to the <End> block.
    void pageDown(std::uint32_t rows);
    /// <Pos1>: N0000 (the first block). O(1).
    void home();
    /// <End>: the block before the end of the program. O(1).
    void end();
    /// Puts the cursor on `block` (clamped to the selectable blocks).
    void moveTo(std::uint32_t block);

    // ---- Plane+ / Plane- (seed 000, 2.5)
    /// Follows the jump or call in the cursor block into a new level, or
    /// opens the event / variable window first (then window() says which).
    /// Refused (nothing changes) for a block without jump, BST/RET/RTS, a
    /// missing label or program, a cycle, or when the 10th level is reached.
    SearchReply planePlus();
    /// Event window: follow the jump with the event shown as `set` (the
    /// change is recorded for the computing process). Refused when no event
    /// window is open.
    SearchReply confirmEvent(bool set);
    /// Variable window: follow the jump to program `value` (a changed value
    /// is recorded). Refused, window left open, when the value is not a whole
    /// program number of this process or the program does not exist.
    SearchReply confirmVariable(double value);
    /// Closes an open window without jumping.
    void cancelWindow();
    const PlaneWindow& window() const { return window_; }
    /// Back to the calling point of the current level. Refused on level 0.
    SearchReply planeMinus();

    // ---- search, start block, runs
    /// Moves the cursor to the next block after it whose text (comments
    /// included) contains `text`, case-insensitive, towards the end of the
    /// displayed program. Does not wrap: refused with "not found" (cursor
    /// stays) when there is no further occurrence.
    SearchReply search(std::string_view text);
    /// Switches "restart from last primary block" on or off. Refused (stays
    /// off) when there is no primary block before the target.
    SearchReply setFromLastPrimary(bool on);
    bool fromLastPrimary() const { return fromLastPrimary_; }
    /// Where the computing process would start for the cursor as it is now.
    /// std::nullopt when "from last primary block" is on but there is none.
    std::optional<StartBlock> startBlock() const;
    /// Number of runs from the operator's text (1..65536, seed 000, 2.6).
    /// Refused (old value kept) for anything else, with the reason.
    SearchReply setRuns(std::string_view text);
    std::uint32_t runs() const { return runs_; }
    /// After each computing process the number of runs goes back to 1.
    void computingProcessDone() { runs_ = kMinRuns; }

    /// <Enter>: validates the target and builds the selection with warnings
    /// (subroutine at the program start, start block after G91/G51).
    AcceptResult accept() const;

    // ---- what the screen shows
    const std::vector<SearchLevel>& levels() const { return levels_; }
    /// The displayed level (the innermost). Precondition: active().
    const SearchLevel& current() const { return levels_.back(); }
    const ProgramScan& currentScan() const { return scan(current().program); }
    /// The jump or call that opened `level` as written ("BSR .CONTUR",
    /// "JSR @10"); "" for level 0.
    std::string levelCommand(std::size_t level) const;
    /// The program levels of the way to the target (outermost first).
    std::vector<ProgramLevel> programLevels() const;
    /// The levels of the whole path, split at its JMPs (main program first).
    std::vector<LevelSegment> programSegments() const;
    /// Variables and events changed in the windows so far.
    const std::map<int, double>& variableChanges() const { return variableChanges_; }
    const std::map<EventRef, bool>& eventChanges() const { return eventChanges_; }
    int process() const { return process_; }

  private:
    const ProgramScan& scan(const ProgramPtr& program) const;
    SourceLocation where(const SearchLevel& level, std::uint32_t block) const;
    SearchReply refuse(std::string code, std::string message) const;
    SearchReply openEventWindow(const SearchJump& jump);
    SearchReply follow(const SearchJump& jump);
    SearchReply enterLabel(const SearchJump& jump);
    SearchReply enterProgram(const SearchJump& jump, int number);
    SearchReply openLevel(const SearchJump& jump, ProgramPtr program, std::uint32_t block);
    bool readJump(const ProgramPtr& program, std::uint32_t block, SearchJump& jump) const;
    bool resolveLabel(std::string_view name, const ProgramPtr& current, ProgramPtr& program,
                      std::uint32_t& block) const;

    const ProgramStore& store_;
    int process_;
    SearchSources sources_;
    std::vector<SearchLevel> levels_;
    PlaneWindow window_;
    std::optional<SearchJump> pending_;  ///< the command behind an open window
    bool fromLastPrimary_ = false;
    std::uint32_t runs_ = kMinRuns;
    std::map<int, double> variableChanges_;
    std::map<EventRef, bool> eventChanges_;
    mutable std::map<const Program*, std::unique_ptr<ProgramScan>> scans_;
};

}  // namespace mtc::core
