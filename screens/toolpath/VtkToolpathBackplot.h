#pragma once

// The backplot of the VTK toolpath view (TP-016), one per picture area.
#include <vtkActor.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <QColor>
#include <cstdint>
#include <vector>

#include "screens/toolpath/ToolpathModel.h"

namespace mtc::screens {

/// What a running program has travelled since Start, drawn over the path in
/// one renderer: the travelled segments in sealed pieces of kPieceSegments,
/// built once and never uploaded again, and an open piece (the rest and the
/// travelled part of the segment the axes are on) rebuilt at each change,
/// so that a step of the station uploads at most kPieceSegments segments
/// whatever the length of the backplot.
class VtkBackplot {
  public:
    static constexpr std::uint32_t kPieceSegments = 4096;
    /// Line width in pixels at 96 dpi: wider than the path (1 px), narrower
    /// than the highlight (6 px), so the running block's travelled part shows on it.
    static constexpr double kWidth = 3.0;

    /// Sealed pieces go to `steady`, the open piece to `live` (VtkStillCache).
    VtkBackplot(vtkRenderer* steady, vtkRenderer* live, const QColor& colour);
    ~VtkBackplot();
    VtkBackplot(const VtkBackplot&) = delete;
    VtkBackplot& operator=(const VtkBackplot&) = delete;

    /// Shows `backplot` (empty: nothing). Returns true when a piece was
    /// sealed or the backplot started over (the steady part changed).
    bool show(const ToolpathBackplot& backplot);
    /// Lines `width` device pixels wide (kWidth scaled to the screen, TP-026).
    void setWidth(float width);
    /// Removes every piece.
    void clear();
    /// Shows or hides the sealed pieces (the open piece stays as it is).
    void setSealedVisible(bool visible);
    /// The open piece: the part of the backplot that changes with each step.
    vtkActor* open() const { return open_; }
    /// Segments in sealed pieces.
    std::uint32_t sealedSegments() const { return sealedSegments_; }

  private:
    vtkSmartPointer<vtkActor> newActor() const;

    vtkRenderer* steady_;
    vtkRenderer* live_;
    QColor colour_;
    float width_ =
        static_cast<float>(kWidth);  ///< device pixels; before open_, newActor() reads it
    std::vector<vtkSmartPointer<vtkActor>> sealed_;
    vtkSmartPointer<vtkActor> open_;
    std::uint64_t run_ = 0;
    std::uint64_t revision_ = 0;
    const mtc::core::ToolpathLayer* layer_ = nullptr;
    std::uint32_t sealedSegments_ = 0;
    bool sealedVisible_ = true;
};

}  // namespace mtc::screens
