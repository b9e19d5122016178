#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <array>
#include <memory>
#include <vector>

#include "cnc_core/language/Program.h"
#include "cnc_core/removal/LiveCut.h"
#include "cnc_core/removal/ProgramStock.h"
#include "cnc_core/toolpath/RunTrace.h"
#include "cnc_core/toolpath/Stock.h"
#include "cnc_core/toolpath/ToolpathRun.h"
#include "screens/toolpath/ToolpathPalette.h"

namespace mtc::hmi {
class CellSession;
}

namespace mtc::screens {

class RestartController;
class ToolpathLink;

/// The marks the restart screen contributes to the picture (scene coordinates).
struct ToolpathMarks {
    bool hasStart = false, hasTarget = false, hasReentry = false, hasRepos = false;
    std::array<double, 3> start{}, target{}, reentry{}, actual{};
    /// The REPOS path (hasRepos): where the axes stand, then the end of every
    /// move the rest of ADJUST and REPOS commands (TP-007), scene points.
    std::vector<std::array<double, 3>> repos;
    /// Where a move of the way back first meets the part at the target
    /// (the result review's collisions, D-021), scene points.
    std::vector<std::array<double, 3>> collisions;
    /// The tool where the axes are now (TP-015): the scene point of the
    /// machine's actual position, the edge in use (radius, length L1; 0 when
    /// the tool list has no such edge) and whether the station turns.
    bool hasTool = false;
    std::array<double, 3> tool{};
    double toolRadius = 0.0;
    double toolLength = 0.0;
    bool turning = false;
};

/// What the view draws of the backplot in one layer (TP-016): the first
/// `segments` segments of `layer` (the station's run trace), and when the
/// axes are inside a segment, the travelled part of it (partialFrom to
/// partialTo). `run` changes with every new run, `revision` with every change.
struct ToolpathBackplot {
    const mtc::core::ToolpathLayer* layer = nullptr;  ///< null: no backplot to draw
    std::uint32_t segments = 0;
    bool partial = false;
    std::array<double, 3> partialFrom{}, partialTo{};
    std::uint64_t run = 0;
    std::uint64_t revision = 0;

    bool empty() const { return !layer || (segments == 0 && !partial); }
};

/// The finished part the view shows (TP-023): the program's stock cut by
/// its whole run, as `mtc200-cli simulate` cuts it, as triangles.
struct ToolpathPart {
    std::vector<float> triangles;  ///< 9 floats (three corners, scene mm) per triangle
    bool heightField = false;      ///< a milled z-map (else a turned profile)
    /// "Finished part: 69,471 mm³ removed at 0.2 mm" or why there is none.
    QString note;
};

/// The model behind the toolpath view of one station (no display code):
/// the geometry of the station's selected program (built by running it on
/// a private interpreter into a ToolpathBuilder), the stock of the machine
/// configuration, the highlighted block and the marks of the restart
/// screen (start block, target block, re-entry point, REPOS path). It
/// follows the screen the station's ToolpathLink names (the restart
/// controller or the editor): moving its cursor highlights the block;
/// picking a segment here puts the cursor there (TP-006, TP-012). While the
/// station's program runs, the running block is highlighted instead
/// (TP-017), and the station's run trace is the backplot (TP-016).
class ToolpathModel : public QObject {
    Q_OBJECT
  public:
    /// The model of station `slot`; `session` must outlive it.
    ToolpathModel(mtc::hmi::CellSession* session, int slot,
                  std::shared_ptr<RestartController> restart, std::shared_ptr<ToolpathLink> link,
                  QObject* parent = nullptr);
    ~ToolpathModel() override;

    /// Rebuilds the geometry when the selected program changed since the last
    /// build (emits geometryChanged) and re-reads highlight and marks.
    void refresh();
    /// Builds the geometry of program `number` now, whether it changed or not.
    void build(int number);

    std::shared_ptr<const mtc::core::ToolpathGeometry> geometry() const { return geometry_; }
    int programNumber() const { return number_; }
    /// "P1 DRIVE SHAFT · 1234 moves · 5678 segments · tolerance 0.01 mm" or why nothing is shown.
    QString summary() const;
    /// The first problem of the last build ("" when it ran cleanly).
    QString problem() const { return problem_; }
    const mtc::core::Stock& stock() const { return stock_; }
    /// What the view frames and labels in the scene (developed) picture: the
    /// cutting moves and, in the scene, the stock, so that an approach or a
    /// tool change far away does not shrink the part to a corner (TP-014);
    /// with `all`, every move. Falls back to every move when nothing cuts.
    /// The restart's marks and REPOS path are always inside.
    mtc::core::ToolpathBounds frame(bool developed, bool all) const;
    const ToolpathPalette& palette() const { return palette_; }
    ToolpathMarks marks() const;
    /// Moves of the highlighted block, every execution of it (empty = none).
    const std::vector<std::uint32_t>& highlighted() const { return highlighted_; }
    /// "P1 N0012 (line 14)" of the highlighted block, or "".
    QString highlightText() const { return highlightText_; }
    /// The highlighted block is the one the running program executes (TP-017).
    bool highlightsRunningBlock() const { return highlightRunning_; }
    /// The backplot of the scene (developed) layer: what the station's
    /// program run has travelled since its Start, when the run is one of the
    /// program shown (TP-016); empty otherwise.
    ToolpathBackplot backplot(bool developed) const;
    /// The workpiece frame the view labels its axes in (TP-019): the zero
    /// offset in force at the running move while the program runs, else at
    /// the picked move or the highlighted block's first move (for a block
    /// without motion the next move of its program), else at the path's end.
    mtc::core::ToolpathFrame workFrame() const;
    /// "X (mm, G54)": the title of scene axis `axis` (0..2) in workFrame();
    /// the axis G15/G16 apply to says "Ø" under G16 and, on a lathe,
    /// "radius" under G15 (TP-020).
    QString axisTitle(int axis) const;
    /// The station turns (default plane G18, as the part model decides).
    bool turning() const;
    /// "Workpiece coordinates G54: zero point at machine ..." or
    /// "Machine coordinates (G53, no zero offset)"; "" without a path.
    QString frameCaption() const;
    /// The part the view draws: while the station's run of the program shown
    /// has a live part (TP-027), that part as the tool has cut it so far;
    /// else the finished part (TP-023), simulated with the geometry for
    /// programs of up to kPartBlocks blocks, else when togglePart() asks.
    const ToolpathPart& part() const { return showingLive_ ? livePart_ : part_; }
    bool partShown() const { return partShown_ && !part().triangles.empty(); }
    /// The part drawn is the station's, cut as its axes travel.
    bool partIsLive() const { return showingLive_; }
    /// The key M: shows or hides the part; the first time on a large
    /// program it simulates the finished part (which takes a while).
    void togglePart();
    /// Least time between two meshes of the live part while the axes move
    /// (each new mesh redraws the steady picture: a full frame on llvmpipe).
    static constexpr int kLiveMeshMs = 400;
    static constexpr std::size_t kPartBlocks = 200'000;
    /// The tolerance the next build tessellates with (mm).
    void setTolerance(double millimetres);
    double tolerance() const { return settings_.tolerance; }

    /// "restart" or "editor": the screen the view is linked to.
    QString partnerName() const;
    /// The operator picked move `move` (a segment of it) in the view: its
    /// block is highlighted and becomes the linked screen's cursor (the
    /// editor's line; the restart cursor, now when that program is displayed
    /// there and at the next entry). Out of range: nothing happens.
    void pick(long move);
    /// Picks the move after (+1) or before (-1) the current move (the one
    /// picked last, or the first of the highlighted block).
    void step(int direction);

  signals:
    /// A new geometry (or none).
    void geometryChanged();
    /// The highlighted block or a mark changed.
    void marksChanged();
    /// The finished part was simulated or shown / hidden.
    void partChanged();
    /// The operator picked a segment of block `block` of program `program`.
    void blockPicked(int program, std::uint32_t block);

  private:
    /// Cuts the stock with the program shown (removal::simulateRemoval).
    void simulatePart();
    /// Takes the station's live part when it belongs to a run of the
    /// program shown and changed (at most every kLiveMeshMs while moving).
    void followLiveCut();
    /// The triangles and the legend's note of the live part.
    void meshLivePart(const mtc::core::removal::LiveCut& cut, bool moving);
    void followPartner();
    /// While the station's program is active: highlights the block of the
    /// move the machine executes (TP-017); false when there is none.
    bool followRunningBlock();
    /// The station's run trace when it is a run of the program shown.
    const mtc::core::RunTrace* trace() const;
    void followRestartCursor();
    void followEditorCursor();
    /// Re-interprets the rest of ADJUST / REPOS while a restart waits for or
    /// runs them (ReposPreview); clears the path otherwise.
    void updateReposPath();
    void setHighlight(int program, std::uint32_t block);
    /// Puts the restart screen's cursor on the block when it shows that program.
    void showInRestartListing(int program, std::uint32_t block);
    /// The tool marker of `marks` from the station's machine now.
    void markTool(ToolpathMarks& marks) const;
    std::array<double, 3> firstPointOf(int program, std::uint32_t block, bool& found) const;
    /// The first move of the block or after it in the same program, or -1.
    long moveAtOrAfter(int program, std::uint32_t block) const;

    mtc::hmi::CellSession* session_;
    int slot_;
    std::shared_ptr<RestartController> restart_;
    std::shared_ptr<ToolpathLink> link_;
    std::vector<std::array<double, 3>> reposPath_;
    mtc::core::ToolpathSettings settings_;
    std::shared_ptr<const mtc::core::ToolpathGeometry> geometry_;
    std::unique_ptr<mtc::core::ToolpathBuilder> mapping_;  ///< scene points of positions
    mtc::core::ProgramPtr built_;
    int number_ = 0;
    QString problem_;
    bool complete_ = false;
    mtc::core::Stock stock_;
    /// The program's stock as worked out for the path (its window, TP-008),
    /// reused by the part's simulation.
    std::shared_ptr<const mtc::core::removal::ProgramStock> programStock_;
    ToolpathPart part_;
    bool partShown_ = true;
    bool partSimulated_ = false;  ///< part_ belongs to the program built
    ToolpathPart livePart_;
    bool showingLive_ = false;
    std::uint64_t liveRun_ = 0, liveRevision_ = 0;  ///< of the live part meshed last
    QElapsedTimer liveMeshed_;
    bool liveFollowPending_ = false;  ///< a later look is scheduled
    bool liveMoving_ = false;         ///< the station was busy at the last mesh (its note)
    /// cuttingBounds of the geometry, scene and developed (set by build()).
    std::array<mtc::core::ToolpathBounds, 2> cutting_;
    ToolpathPalette palette_;
    std::vector<std::uint32_t> highlighted_;
    QString highlightText_;
    bool highlightRunning_ = false;
    int highlightProgram_ = -1;
    std::uint32_t highlightBlock_ = 0;
    long currentMove_ = -1;
    /// The move whose zero offset the view names when no program runs
    /// (TP-019), and the block it was found for (-1: none).
    long frameMove_ = -1;
    int frameProgram_ = -1;
    std::uint32_t frameBlock_ = 0;
};

}  // namespace mtc::screens
