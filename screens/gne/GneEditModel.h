#pragma once

// The model of the GNE screen (seed 001, ch. 3): one section of GNE
// instructions of an NC program (the adjacent WINDOW_0x, CONT ... END_CONT,
// FORM_xx and CYCLE_xx lines around the cursor, or a new one), edited as a
// list of rows (items and contour elements) with checked parameter entry,
// the solver's results, alternatives, undo/redo and the two ways back into
// the program: keyword text (function call) or expanded NC blocks.
// Plain C++ (no Qt): the screen renders it.

#include <string>
#include <vector>

#include "cnc_core/contour/ContourSolver.h"
#include "cnc_core/contour/GneExpansion.h"
#include "cnc_core/contour/GneModel.h"
#include "screens/gne/GneFields.h"
#include "screens/gne/GneNumbering.h"

namespace mtc::screens {

/// One row of the list: an item (element = -1) or an element of a contour.
struct GneRow {
    int item = 0;
    int element = -1;
};

/// How the dialog ends (seed 001 ch. 3: the operator chooses).
enum class GneOutput { FunctionCall, NcBlocks };

class GneEditModel {
  public:
    /// Opens the dialog on `programText` at 1-based source `line`: the
    /// section of GNE instructions containing the line is modified, an empty
    /// or other line gets a new section (a CONT, with a WINDOW when none
    /// precedes). Line 0 = the program's first section, else new at the end.
    void open(const std::string& programText, int line);
    /// Opens on a text that holds only GNE instructions (tests, round trip).
    void openText(const std::string& gneText) { open(gneText, 1); }

    /// True when the section did not exist in the program.
    bool isNew() const { return firstLine_ == 0; }
    /// 1-based program lines the section occupies (0 when new).
    int firstLine() const { return firstLine_; }
    int lastLine() const { return lastLine_; }
    /// Problems the reader found in the section's lines when it was opened.
    const std::vector<mtc::core::gne::GneDiagnostic>& readProblems() const { return readProblems_; }

    const std::vector<mtc::core::gne::GneItem>& items() const { return items_; }
    const std::vector<GneRow>& rows() const { return rows_; }
    /// Text of row `row` as in the program ("LINE Z-20 X15 TAN").
    std::string rowText(int row) const;
    int currentRow() const { return current_; }
    void setCurrentRow(int row);
    /// Plane of item `item` (from the last window before it).
    mtc::core::gne::GnePlane planeOf(int item) const;
    /// Plane of the window before the section in the program (turning if none).
    mtc::core::gne::GnePlane contextPlane() const { return contextPlane_; }

    /// The values of the current row.
    std::vector<gnefields::Field> fields() const;
    /// Sets value `index` of the current row from operator `text`; false
    /// with a message when refused (the old value stays).
    bool setField(int index, const std::string& text, gnefields::ModelText& message);

    /// What may be inserted after the current row ("LINE", "CYCLE_11", ...).
    std::vector<std::string> insertChoices() const;
    /// Inserts `choice` after the current row and selects it.
    bool insert(const std::string& choice, gnefields::ModelText& message);
    /// Deletes the current row (a CONT row deletes the whole contour).
    bool removeCurrent(gnefields::ModelText& message);

    /// Number of solutions of the current element (>1: alternatives).
    int alternativeCount() const;
    /// Chooses the current element's next solution (wraps around).
    bool nextAlternative();

    bool canUndo() const { return !undo_.empty(); }
    bool canRedo() const { return !redo_.empty(); }
    bool undo();
    bool redo();
    /// True once anything was changed since open().
    bool modified() const { return modified_; }

    /// Solver result of contour item `item` (empty for other items).
    const mtc::core::gne::ContourSolution& solution(int item) const;
    /// Geometry, cycle blocks and diagnostics of the whole section.
    const mtc::core::gne::GneExpansion& expansion() const { return expansion_; }
    /// Blank of the window that applies (known = false when none).
    bool window(double& low0, double& low1, double& high0, double& high1) const;
    /// What the reader found wrong when the section was opened (dropped
    /// words, ...) and sectionProblems(), one per line ("" = none).
    std::string problems() const { return gnefields::englishLines(problemTexts()); }
    std::vector<gnefields::ModelText> problemTexts() const;
    /// Why the section as it is now does not solve or expand, by row ("" =
    /// it does): both exits refuse to save while this is not empty.
    std::string sectionProblems() const { return gnefields::englishLines(sectionProblemTexts()); }
    std::vector<gnefields::ModelText> sectionProblemTexts() const;

    /// The section as keyword lines (function call with parameters).
    std::string keywordText() const;
    /// The section as NC blocks: cycles expanded, windows and geometry as
    /// comments. False with `problem` when the section does not expand.
    bool ncBlocks(std::string& text, gnefields::ModelText& problem) const;
    /// What goes back into the program for `kind`, numbered as the
    /// program (GS-007): lines that stem from program lines keep their
    /// block numbers and comments, new lines get "N0053:0001" after the
    /// numbered line before them. An unchanged section as function call is
    /// returned exactly as it was. False with `problem` when NC blocks are
    /// refused (see ncBlocks).
    bool output(GneOutput kind, std::string& text, gnefields::ModelText& problem) const;
    /// The program text with the section replaced by `output` (lines).
    std::string splice(const std::string& output) const;
    /// Line of the section's first line in splice()'s result.
    int spliceLine() const;

  private:
    /// The section as keyword lines with the program lines they stem from.
    std::vector<GneOutputLine> keywordLines() const;
    /// The section as NC block lines (see ncBlocks) with their origins.
    bool ncBlockLines(std::vector<GneOutputLine>& lines, gnefields::ModelText& problem) const;

    struct Snapshot {
        std::vector<mtc::core::gne::GneItem> items;
        int current = 0;
    };
    void pickSection(const std::string& programText, int line);
    void startNew(int line);
    void selectLine(int line);
    void changed();
    void remember();
    void buildRows();
    mtc::core::gne::GneDocument document(bool withContext) const;
    int nextGeometryNumber() const;
    int currentContourItem() const;
    mtc::core::gne::ContourElement* currentElement();

    std::vector<std::string> programLines_;
    std::vector<mtc::core::gne::GneItem> items_;
    std::vector<GneRow> rows_;
    std::vector<mtc::core::gne::ContourSolution> solutions_;
    mtc::core::gne::GneExpansion expansion_;
    std::vector<mtc::core::gne::GneDiagnostic> readProblems_;
    std::vector<int> usedNumbers_;                       ///< geometry numbers outside the section
    std::vector<mtc::core::gne::GneItem> contextItems_;  ///< windows, geometry before it
    mtc::core::gne::GneCall contextWindow_;
    bool hasContextWindow_ = false;
    mtc::core::gne::GnePlane contextPlane_ = mtc::core::gne::GnePlane::Turning;
    int firstLine_ = 0;
    int lastLine_ = 0;
    int insertLine_ = 0;  ///< new section: goes before this line (1-based)
    bool replaceEmptyLine_ = false;
    int current_ = 0;
    bool modified_ = false;
    std::vector<Snapshot> undo_;
    std::vector<Snapshot> redo_;
};

}  // namespace mtc::screens
