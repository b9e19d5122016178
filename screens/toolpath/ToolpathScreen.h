#pragma once

#include <memory>

#include "hmi/Screen.h"
#include "screens/toolpath/ToolpathCamera.h"

class QLabel;

namespace mtc::screens {

class RestartController;
class ToolpathCanvas;
class ToolpathLink;
class ToolpathModel;

/// Says whether an OpenGL context can be made here, before anything of VTK
/// is created (VTK's X render window aborts the process without one). No
/// with the reason for the platforms "offscreen" and "minimal", when the
/// environment variable MTC_TOOLPATH_2D is set, or when no context can be
/// created and made current on an offscreen surface.
bool openGlAvailable(QString& reason);

/// Toolpath graphics of the station's selected program ("toolpath"): the 3D
/// view (VTK) or, without OpenGL, the 2D view, with the current block
/// highlighted (the cursor of the restart screen or of the editor, TP-012;
/// while the program runs the running block, TP-017), the backplot of the
/// run since Start (TP-016), the tool where the axes are (TP-015) and the
/// restart screen's start and target blocks, re-entry point and REPOS path
/// marked. Keys: 1/2/3/4 G17/G18/G19/isometric view,
/// 0 or Home fit, + / − zoom, arrows rotate, Shift+arrows pan, PgDn/PgUp
/// next/previous move (moves the linked screen's cursor), P export PNG.
class ToolpathScreen : public mtc::hmi::Screen {
    Q_OBJECT
  public:
    /// `link` says whether the view follows the restart screen or the editor.
    ToolpathScreen(const mtc::hmi::ScreenContext& context,
                   std::shared_ptr<RestartController> restart, std::shared_ptr<ToolpathLink> link);
    ~ToolpathScreen() override;
    QString screenName() const override { return "toolpath"; }
    QString title() const override {
        return QCoreApplication::translate("ScreenTitle", "Toolpath graphics");
    }
    mtc::hmi::SoftKeys softKeys() override;
    void activated() override;

    ToolpathModel* model() const { return model_; }
    ToolpathCanvas* canvas() const { return canvas_; }
    /// Writes the view as PNG to `path` (atomically). False with the reason
    /// on the message line when it cannot.
    bool exportPng(const QString& path);

  protected:
    void keyPressEvent(QKeyEvent* event) override;

  private:
    void preset(ToolpathPreset preset);
    /// F5: frames the part, or when it is framed, every move (the rapids of
    /// an approach or tool change too); the key says which comes next.
    void fitNext();
    /// Frames the part (presets, Home, a new program) and says so on F5.
    void fitPart();
    void renderText();
    /// The legend line: the motion colours of the tool-centre path, the
    /// programmed contour when the program has compensated moves, and the
    /// backplot when there is one (TP-016).
    QString legendText() const;
    QString defaultExportPath() const;

    std::shared_ptr<RestartController> restart_;
    ToolpathModel* model_;
    ToolpathCanvas* canvas_;
    QLabel* summary_;
    QLabel* legend_;  ///< what the colours mean (tool-centre path, programmed contour)
    QLabel* message_;
    QString glReason_;
    bool showingAll_ = false;  ///< the last fit framed every move
};

}  // namespace mtc::screens
