#pragma once

#include <cstddef>
#include <memory>

#include "screens/toolpath/ToolpathCanvas.h"
#include "screens/toolpath/ToolpathFramePacer.h"

class QVTKOpenGLNativeWidget;

namespace mtc::screens {

/// The 3D toolpath view with VTK (QVTKOpenGLNativeWidget): one poly-data
/// with point colours per layer, a decimated coarse copy in its own actor
/// while the view moves (level of detail, TP-010), the highlighted block, the restart marks and
/// REPOS path, the stock, axes triad, grid with the extents and their dimensions. With G32 moves
/// the developed plane (left) and the wrapped cylinder (right) are shown side by side. Render
/// requests are coalesced and paced to ToolpathFramePacer's rate. Needs an OpenGL context: create
/// it only after openGlAvailable() said yes (VTK aborts the process without one).
class VtkToolpathCanvas : public ToolpathCanvas {
    Q_OBJECT
  public:
    VtkToolpathCanvas(ToolpathModel* model, QWidget* parent = nullptr);
    ~VtkToolpathCanvas() override;

    void showPreset(ToolpathPreset preset) override;
    void fit() override;
    void fitAll() override;
    void zoom(double factor) override;
    void pan(double right, double up) override;
    void rotate(double azimuth, double elevation) override;
    QImage picture() override;
    bool threeD() const override { return true; }
    std::optional<QPoint> positionOfMove(long move) override;
    /// Renders now (tests, frame timing); otherwise renders are coalesced
    /// and paced: at most one per frame interval (TP-029).
    void renderNow();
    /// Least time between the starts of two paced renders (0: one per
    /// event-loop pass, as the tests that step the station use).
    void setFrameInterval(int milliseconds) { pacer_.setInterval(milliseconds); }
    int frameInterval() const { return pacer_.interval(); }
    /// A render was asked for and waits for its time.
    bool framePending() const { return pacer_.pending(); }
    /// Renders done so far (coalescing check).
    int renderCount() const;
    /// Renders that drew the steady picture from the kept image (TP-018).
    int keptRenders() const;
    /// Steady pictures drawn and kept since the view was made (TP-018).
    int keptPictures() const;
    /// Off: every render draws the whole scene (frame timing, tests).
    void keepSteadyPicture(bool on);
    /// True while the coarse copy is shown (the view is moving).
    bool showingLevelOfDetail() const;
    /// Cells of the scene's coarse copy (0 when the full path is small enough).
    std::size_t levelOfDetailCells() const;
    /// Line cells of the scene's full picture (repeats dropped, TP-022).
    std::size_t fullCells() const;
    /// Picks resolved through the coarse copy's cells to a full segment.
    int picksOnLevelOfDetail() const;
    /// The scene's caption and the range the tick labels of scene axis
    /// `axis` (0 X, 1 Y, 2 Z) read, in the workpiece frame (TP-019).
    QString sceneCaption() const;
    std::array<double, 2> tickRange(int axis) const;
    /// Where the scene's caption and the axes triad are drawn (widget pixels).
    QRect sceneCaptionRect() const;
    QRect triadRect() const;
    /// The scene's framed box (ToolpathModel::frame) on the screen.
    QRect framedRect() const;
    /// The title the axes box shows on scene axis `axis` (0 X, 1 Y, 2 Z).
    QString axisTitle(int axis) const;
    /// Cells the coarse copy shown while moving may have at most.
    static constexpr std::size_t kLevelOfDetailCells = 40000;
    /// Its starting tolerance: this fraction of the layer's largest extent
    /// (about one pixel of a 1000-pixel view that shows the whole path).
    static constexpr double kLevelOfDetailTolerance = 1.0 / 1000.0;

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    struct Scene;
    /// A box (x min, x max, y min, y max; device pixels up from the
    /// bottom, as VTK gives them) in widget pixels.
    QRect deviceToWidget(const double box[4]) const;
    /// Sets the line widths for the screen the view is on now (TP-026; VTK
    /// draws in device pixels, known once the view is in its window).
    void updateLineWidths();
    /// Line widths and text sizes of both areas and of the marks for `scale`.
    void applyLineScale(double scale);
    void rebuild();
    /// The highlighted moves (uploaded again with `always` or when they
    /// changed). True when the picture changed.
    bool updateHighlight(bool always);
    /// The restart's marks and REPOS path (steady picture: redrawn with
    /// `always` or when they changed) and the tool (live, each time). True
    /// when the picture changed.
    bool updateMarks(bool always);
    /// What the running program has travelled since Start (TP-016). True
    /// when the picture changed.
    bool updateBackplot();
    /// The finished part (TP-023), shown or hidden as the model says.
    void updatePart();
    /// The scene's tick labels, titles and caption in the model's workpiece
    /// frame (TP-019): relabelled with `always` or when the frame changed.
    /// True when the picture changed.
    bool updateFrame(bool always);
    void requestRender() { pacer_.request(); }
    void moving();
    void showLevelOfDetail(bool coarse);
    /// Frames ToolpathModel::frame (the part, or with `all` every move).
    void frame(bool all);
    /// Labels the axes of the picture's plane only in a plane view (the
    /// axis along the view would be a point), all three otherwise.
    void showAxesFor(ToolpathPreset preset);
    void pickAt(QPoint position);

    QVTKOpenGLNativeWidget* widget_;
    ToolpathFramePacer pacer_;  ///< renders at a bounded rate (TP-029)
    std::unique_ptr<Scene> scene_;
};

}  // namespace mtc::screens
