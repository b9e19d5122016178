#pragma once

// The steady picture of the VTK toolpath view, kept as an image while only
// the tool, the highlight and the backplot's open piece change (TP-018).
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>

#include <array>
#include <cstdint>
#include <vector>

namespace mtc::screens {

/// Draws what changes while a program runs without drawing the path again.
/// Each picture area has two renderers on one camera and viewport: `steady`
/// (layer 0: the path, its coarse copy, contour, axes, stock, marks, the
/// backplot's sealed pieces) and `live` (layer 1: the tool, the highlight,
/// the backplot's open piece; it clears the depth, so live props lie over
/// the steady picture the same way in both modes). When a render finds the
/// cameras and the window as the last render left them, the steady
/// renderers draw once alone, their pixels become the live renderers'
/// background texture and the steady renderers stop drawing: a frame then
/// costs the texture and the live props, not the million lines. Any render
/// (the widget's, the interactor's) first checks the cameras and the window
/// size; a change draws everything again, invalidate() the steady picture.
class VtkStillCache {
  public:
    explicit VtkStillCache(vtkRenderWindow* window);
    ~VtkStillCache();
    VtkStillCache(const VtkStillCache&) = delete;
    VtkStillCache& operator=(const VtkStillCache&) = delete;

    /// A picture area (`live` is put on layer 1 and shares `steady`'s camera).
    void addArea(vtkRenderer* steady, vtkRenderer* live);
    /// Something of the steady picture changed: the next render draws it.
    void invalidate();
    /// Renders the window; with `mayKeep`, keeps the steady picture as an
    /// image when it did not change since the last render.
    void render(bool mayKeep);
    /// Off: every render draws everything (the frame timing's "before",
    /// and the test that a kept frame is the full frame). On by default.
    void setEnabled(bool enabled);
    /// Renders that drew the steady picture from the kept image.
    int keptRenders() const { return kept_; }
    /// Steady pictures drawn and kept (each one a draw of the steady renderers).
    int pictures() const { return pictures_; }
    /// The steady picture is drawn from the kept image now.
    bool keeping() const { return keeping_; }

  private:
    struct Area {
        vtkRenderer* steady;
        vtkRenderer* live;
        vtkSmartPointer<vtkTexture> picture;
    };
    /// Camera, viewport and window size: what the kept image depends on.
    std::vector<double> key() const;
    /// Draws the steady renderers alone and keeps their pixels; false when
    /// the pixels cannot be read.
    bool keep();
    /// Draws everything from now on (the kept image is dropped).
    void drop();
    /// Called by the window before every render.
    void beforeRender();

    vtkRenderWindow* window_;
    std::vector<Area> areas_;
    std::vector<double> lastKey_;
    bool keeping_ = false;
    bool capturing_ = false;
    bool enabled_ = true;
    bool unreadable_ = false;  ///< the pixels could not be read: always draw everything
    int kept_ = 0;
    int pictures_ = 0;
    unsigned long observer_ = 0;
};

}  // namespace mtc::screens
