#include "screens/toolpath/VtkToolpathCanvas.h"
#include "screens/toolpath/VtkToolpathActors.h"

#include <QVTKOpenGLNativeWidget.h>
#include <vtkActor.h>
#include <vtkAxesActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCubeAxesActor.h>
#include <vtkCubeSource.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkOrientationMarkerWidget.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyLineSource.h>
#include <vtkProperty.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <QApplication>
#include <QMouseEvent>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "cnc_core/toolpath/ToolpathPick.h"
#include "screens/toolpath/ToolpathModel.h"
#include "screens/toolpath/VtkToolpathCache.h"
#include "screens/toolpath/VtkToolpathData.h"
#include "screens/toolpath/VtkToolpathPart.h"
#include "screens/toolpath/VtkToolpathScene.h"

namespace mtc::screens {

namespace {
constexpr int kStillMs = 250;        ///< full detail again after this pause
constexpr double kPickPixels = 6.0;  ///< a click this close to a segment picks it

/// The marks other than the tool: what the steady picture shows of them.
bool sameSteadyMarks(const ToolpathMarks& a, const ToolpathMarks& b) {
    return a.hasStart == b.hasStart && a.hasTarget == b.hasTarget && a.hasReentry == b.hasReentry &&
           a.hasRepos == b.hasRepos && a.start == b.start && a.target == b.target &&
           a.reentry == b.reentry && a.repos == b.repos && a.collisions == b.collisions;
}

}  // namespace

VtkToolpathCanvas::VtkToolpathCanvas(ToolpathModel* model, QWidget* parent)
    : ToolpathCanvas(model, parent),
      pacer_([this] { renderNow(); }),
      scene_(std::make_unique<Scene>()) {
    setObjectName("toolpathVtk");
    widget_ = new QVTKOpenGLNativeWidget(this);
    widget_->setObjectName("toolpathVtkWidget");
    widget_->setFocusPolicy(Qt::NoFocus);  // keys stay with the screen (VTK's 'e'/'q' would quit)
    widget_->setRenderWindow(scene_->window);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(widget_);
    setMinimumSize(320, 240);

    const ToolpathPalette& palette = model_->palette();
    scene_->developed.developed = true;
    scene_->scene.setUp(palette);
    scene_->developed.setUp(palette);
    applyLineScale(1.0);  // updateLineWidths changes it when the screen's scale differs
    scene_->window->AddRenderer(scene_->scene.renderer);
    scene_->window->AddRenderer(scene_->scene.live);
    scene_->stillCache = std::make_unique<VtkStillCache>(scene_->window);
    scene_->stillCache->addArea(scene_->scene.renderer, scene_->scene.live);
    scene_->stillCache->addArea(scene_->developed.renderer, scene_->developed.live);
    for (vtkActor* a : {scene_->stock.Get(), scene_->cylinder.Get(), scene_->start.Get(),
                        scene_->target.Get(), scene_->reentry.Get(), scene_->repos.Get(),
                        scene_->tool.Get(), scene_->collision.Get(), scene_->part.Get()}) {
        a->PickableOff();
        a->VisibilityOff();
        (a == scene_->tool.Get() ? scene_->scene.live : scene_->scene.renderer)->AddActor(a);
    }
    scene_->window->SetMultiSamples(0);  // lines only: no multisampling (TP-010)

    vtkNew<vtkInteractorStyleTrackballCamera> style;
    widget_->interactor()->SetInteractorStyle(style);
    scene_->interaction->SetClientData(this);
    scene_->interaction->SetCallback([](vtkObject*, unsigned long event, void* self, void*) {
        auto* canvas = static_cast<VtkToolpathCanvas*>(self);
        if (event == vtkCommand::StartInteractionEvent) canvas->moving();
    });
    style->AddObserver(vtkCommand::StartInteractionEvent, scene_->interaction);
    scene_->triad->SetOrientationMarker(scene_->triadAxes);
    scene_->triad->SetInteractor(widget_->interactor());
    scene_->triad->SetCurrentRenderer(scene_->scene.renderer);
    scene_->triad->SetEnabled(1);
    scene_->triad->InteractiveOff();

    scene_->still.setSingleShot(true);
    scene_->still.setInterval(kStillMs);
    connect(&scene_->still, &QTimer::timeout, this, [this] {
        if (widget_->interactor()->GetInteractorStyle() &&
            QApplication::mouseButtons() != Qt::NoButton) {
            scene_->still.start();  // still dragging
            return;
        }
        showLevelOfDetail(false);
        requestRender();
    });
    widget_->installEventFilter(this);
    connect(model_, &ToolpathModel::geometryChanged, this, &VtkToolpathCanvas::rebuild);
    connect(model_, &ToolpathModel::partChanged, this, [this] {
        const bool wasShown = scene_->part->GetVisibility();
        updatePart();
        // A live part meshed again while M hides it changes no pixel (TP-029).
        if (!wasShown && !scene_->part->GetVisibility()) return;
        scene_->stillCache->invalidate();
        requestRender();
    });
    connect(model_, &ToolpathModel::marksChanged, this, [this] {
        // A station change that shows nothing new (a dwell, a spindle
        // running up) renders nothing.
        bool changed = updateHighlight(false);
        changed = updateMarks(false) || changed;
        changed = updateBackplot() || changed;
        changed = updateFrame(false) || changed;
        if (changed) requestRender();
    });
    rebuild();
}

VtkToolpathCanvas::~VtkToolpathCanvas() {
    scene_->triad->SetEnabled(0);
}

int VtkToolpathCanvas::renderCount() const {
    return scene_->renders;
}

int VtkToolpathCanvas::keptRenders() const {
    return scene_->stillCache->keptRenders();
}

int VtkToolpathCanvas::keptPictures() const {
    return scene_->stillCache->pictures();
}

void VtkToolpathCanvas::keepSteadyPicture(bool on) {
    scene_->stillCache->setEnabled(on);
}

bool VtkToolpathCanvas::showingLevelOfDetail() const {
    return scene_->coarse;
}

void VtkToolpathCanvas::updatePart() {
    const bool shown = model_->geometry() && model_->partShown();
    const ToolpathPart& part = model_->part();
    if (shown)
        placeFinishedPart(scene_->part, part.triangles, model_->palette().part, part.heightField);
    scene_->part->SetVisibility(shown);
}

void VtkToolpathCanvas::renderNow() {
    pacer_.drawn();
    updateLineWidths();
    for (Part* part : {&scene_->scene, &scene_->developed})
        if (part->fitCaptionToWidth()) scene_->stillCache->invalidate();
    if (scene_->refitWhenShown && widget_->isVisible()) {
        const bool all = *scene_->refitWhenShown;
        scene_->refitWhenShown.reset();
        for (Part* part : {&scene_->scene, &scene_->developed})
            part->frame(model_->frame(part->developed, all));
    }
    // While the view moves every frame is a new picture: nothing to keep.
    scene_->stillCache->render(!scene_->coarse);
    ++scene_->renders;
}

std::size_t VtkToolpathCanvas::levelOfDetailCells() const {
    return scene_->scene.coarse ? static_cast<std::size_t>(scene_->scene.coarse->GetNumberOfCells())
                                : 0;
}

std::size_t VtkToolpathCanvas::fullCells() const {
    return scene_->scene.full ? static_cast<std::size_t>(scene_->scene.full->GetNumberOfCells())
                              : 0;
}

int VtkToolpathCanvas::picksOnLevelOfDetail() const {
    return scene_->coarsePicks;
}

void VtkToolpathCanvas::showLevelOfDetail(bool coarse) {
    scene_->stillCache->invalidate();
    scene_->coarse = coarse && scene_->scene.coarse;
    for (Part* part : {&scene_->scene, &scene_->developed}) {
        if (!part->full) continue;
        // Two actors, each with its own buffers: switching uploads nothing.
        const bool useCoarse = scene_->coarse && part->coarse;
        part->path->SetVisibility(!useCoarse);
        part->coarsePath->SetVisibility(useCoarse);
    }
}

void VtkToolpathCanvas::moving() {
    scene_->refitWhenShown.reset();  // the operator moved the view: keep it
    if (!scene_->coarse) showLevelOfDetail(true);
    scene_->still.start();
}

void VtkToolpathCanvas::rebuild() {
    const auto g = model_->geometry();
    const ToolpathPalette& palette = model_->palette();
    Scene& s = *scene_;
    s.stillCache->invalidate();
    s.coarse = false;
    s.split = g && g->developed.segmentCount() > 0;
    if (s.split) {
        for (vtkRenderer* r : {s.developed.renderer.Get(), s.developed.live.Get()}) {
            if (!s.window->HasRenderer(r)) s.window->AddRenderer(r);
            r->SetViewport(0, 0, 0.5, 1);
        }
        s.scene.renderer->SetViewport(0.5, 0, 1, 1);
        s.scene.live->SetViewport(0.5, 0, 1, 1);
        s.triad->SetViewport(0.88, 0, 1, 0.2);  // clear of both captions (bottom left)
    } else {
        s.window->RemoveRenderer(s.developed.renderer);
        s.window->RemoveRenderer(s.developed.live);
        s.scene.renderer->SetViewport(0, 0, 1, 1);
        s.scene.live->SetViewport(0, 0, 1, 1);
        s.triad->SetViewport(0.85, 0, 1, 0.2);  // clear of the caption (bottom left)
    }
    for (Part* part : {&s.scene, &s.developed}) {
        const bool shown = g && (part == &s.scene || s.split);
        part->path->SetVisibility(shown);
        part->axes->SetVisibility(shown &&
                                  !(part->developed ? g->developed : g->scene).bounds.empty);
        part->coarsePath->VisibilityOff();
        part->coarse = nullptr;
        part->decimated = {};
        part->coarseMapper->SetInputData(vtkNew<vtkPolyData>());
        const bool contour =
            shown && (part->developed ? g->developedContour : g->contour).segmentCount() > 0;
        part->contour->SetVisibility(contour);
        part->contourMapper->SetInputData(contour ? toolpathContour(*g, part->developed)
                                                  : vtkSmartPointer<vtkPolyData>::New());
        if (!shown) {
            part->full = nullptr;
            part->mapper->SetInputData(vtkNew<vtkPolyData>());
            continue;
        }
        const auto& layer = part->developed ? g->developed : g->scene;
        part->full = toolpathPolyData(*g, part->developed, palette);
        part->mapper->SetInputData(part->full);
        // Cells, not segments: a path that retraces itself may draw few
        // cells (TP-022), and then the full picture moves faster than any copy.
        if (static_cast<std::size_t>(part->full->GetNumberOfCells()) > kLevelOfDetailCells) {
            part->decimated = mtc::core::decimateLayer(
                *g, part->developed, layer.bounds.size() * kLevelOfDetailTolerance,
                kLevelOfDetailCells);
            part->coarse = toolpathLevelOfDetail(*g, part->developed, palette, part->decimated);
            part->coarseMapper->SetInputData(part->coarse);
        }
        const mtc::core::ToolpathBounds framed = model_->frame(part->developed, false);
        setBounds(part->axes, framed);
        labelLongAxesOnly(part->axes, framed);
        if (part->developed) {  // the scene's titles name the zero offset (updateFrame)
            part->axes->SetXTitle(tr("axial (mm)").toUtf8().constData());
            part->axes->SetYTitle(tr("circumference (mm)").toUtf8().constData());
            part->axes->SetZTitle("");
        }
        part->axes->SetUse2DMode(part->developed);
        part->axes->SetZAxisVisibility(!part->developed);
        QString caption =
            part->developed ? tr("Developed plane, G32 RI %1").arg(g->cylinderRadius)
                            : (s.split ? tr("Wrapped on the cylinder RI %1").arg(g->cylinderRadius)
                                       : tr("Toolpath P%1").arg(model_->programNumber()));
        caption += "\n" + extentsText(layer.bounds, part->developed);
        if (part->developed)
            part->caption->SetInput(caption.toUtf8().constData());
        else
            s.sceneCaption = caption;  // the frame's line follows (updateFrame)
    }
    if (!g) s.scene.caption->SetInput(model_->summary().toUtf8().constData());
    if (g) updateFrame(true);
    const auto& stock = model_->stock();
    s.stock->VisibilityOff();
    if (stock.shape == mtc::core::Stock::Shape::Block) {
        vtkNew<vtkCubeSource> cube;
        cube->SetBounds(stock.min[0], stock.max[0], stock.min[1], stock.max[1], stock.min[2],
                        stock.max[2]);
        cube->Update();
        vtkNew<vtkPolyDataMapper> mapper;
        mapper->SetInputData(cube->GetOutput());
        s.stock->SetMapper(mapper);
        s.stock->GetProperty()->SetRepresentationToWireframe();
        s.stock->VisibilityOn();
    } else if (stock.shape == mtc::core::Stock::Shape::Cylinder) {
        placeCylinder(s.stock, stock.axis, stock.radius, stock.from, stock.to);
    }
    setColour(s.stock->GetProperty(), palette.stock);
    s.stock->GetProperty()->SetOpacity(stock.shape == mtc::core::Stock::Shape::Block ? 0.8 : 0.15);
    updatePart();
    s.cylinder->VisibilityOff();
    if (g && g->cylinderAxis >= 0) {
        placeCylinder(s.cylinder, g->cylinderAxis, g->cylinderRadius, g->cylinderFrom,
                      g->cylinderTo);
        setColour(s.cylinder->GetProperty(), palette.stock);
        s.cylinder->GetProperty()->SetOpacity(0.2);
    }
    updateHighlight(true);
    updateMarks(true);
    updateBackplot();
    showPreset(s.preset);
}

bool VtkToolpathCanvas::updateBackplot() {
    bool changed = false;
    for (Part* part : {&scene_->scene, &scene_->developed}) {
        const ToolpathBackplot backplot =
            part->full ? model_->backplot(part->developed) : ToolpathBackplot{};
        const std::array<std::uint64_t, 3> shown{backplot.empty() ? 0u : 1u, backplot.run,
                                                 backplot.revision};
        std::array<std::uint64_t, 3>& before = scene_->shownBackplot[part->developed ? 1 : 0];
        changed = changed || shown != before;
        before = shown;
        if (part->backplot->show(backplot))
            scene_->stillCache->invalidate();  // a piece joined the steady picture
    }
    return changed;
}

void VtkToolpathCanvas::updateLineWidths() {
    const double scale = deviceLineScale();
    if (scale == scene_->scene.screenScale) return;  // both areas and the marks have it
    applyLineScale(scale);
    scene_->stillCache->invalidate();
}

void VtkToolpathCanvas::applyLineScale(double scale) {
    scene_->scene.setScreenScale(scale);
    scene_->developed.setScreenScale(scale);
    scene_->repos->GetProperty()->SetLineWidth(static_cast<float>(scaledWidth(3.0, scale)));
}

bool VtkToolpathCanvas::updateFrame(bool always) {
    const mtc::core::ToolpathFrame frame = model_->workFrame();
    if (!model_->geometry() || (!always && frame == scene_->shownFrame)) return false;
    scene_->shownFrame = frame;
    labelInFrame(scene_->scene.axes, frame,
                 {model_->axisTitle(0).toStdString(), model_->axisTitle(1).toStdString(),
                  model_->axisTitle(2).toStdString()});
    const QString caption = scene_->sceneCaption + "\n" + model_->frameCaption();
    scene_->scene.caption->SetInput(caption.toUtf8().constData());
    scene_->stillCache->invalidate();  // labels and caption are steady picture
    return true;
}

bool VtkToolpathCanvas::updateHighlight(bool always) {
    // The same block at every tick of a running program: nothing to upload.
    if (!always && model_->highlighted() == scene_->shownHighlight) return false;
    scene_->shownHighlight = model_->highlighted();
    const auto g = model_->geometry();
    for (Part* part : {&scene_->scene, &scene_->developed}) {
        if (!g || !part->full) {
            part->highlight->VisibilityOff();
            continue;
        }
        part->highlightMapper->SetInputData(
            toolpathMoves(*g, part->developed, model_->highlighted()));
        part->highlight->SetVisibility(!model_->highlighted().empty());
    }
    return true;
}

bool VtkToolpathCanvas::updateMarks(bool always) {
    const ToolpathMarks marks = model_->marks();
    const ToolpathPalette& palette = model_->palette();
    const auto g = model_->geometry();
    const double size = g ? std::max(g->scene.bounds.size(), 1.0) : 100.0;
    // The tool follows the station (live); the rest is steady picture.
    // A new shape when the edge changes; otherwise only the position moves.
    const std::array<double, 4> shape{marks.hasTool ? 1.0 : 0.0, marks.turning ? 1.0 : 0.0,
                                      marks.toolRadius, marks.toolLength};
    if (always || shape != scene_->toolShape || size != scene_->toolPictureSize)
        placeTool(scene_->tool, marks, size);
    else
        scene_->tool->SetPosition(marks.tool[0], marks.tool[1], marks.tool[2]);
    const bool toolChanged = always || shape != scene_->toolShape ||
                             size != scene_->toolPictureSize || marks.tool != scene_->toolAt;
    scene_->toolShape = shape;
    scene_->toolPictureSize = size;
    scene_->toolAt = marks.tool;
    setColour(scene_->tool->GetProperty(), palette.tool);
    if (!always && sameSteadyMarks(marks, scene_->shownMarks)) return toolChanged;
    scene_->shownMarks = marks;
    scene_->stillCache->invalidate();
    auto sphere = [&](vtkActor* actor, bool shown, const std::array<double, 3>& at,
                      const QColor& colour) {
        actor->SetVisibility(shown);
        if (!shown) return;
        vtkNew<vtkSphereSource> source;
        source->SetCenter(at[0], at[1], at[2]);
        source->SetRadius(size * 0.015);
        source->Update();
        vtkNew<vtkPolyDataMapper> mapper;
        mapper->SetInputData(source->GetOutput());
        actor->SetMapper(mapper);
        setColour(actor->GetProperty(), colour);
    };
    sphere(scene_->start, marks.hasStart, marks.start, palette.start);
    sphere(scene_->target, marks.hasTarget, marks.target, palette.target);
    sphere(scene_->reentry, marks.hasReentry, marks.reentry, palette.reentry);
    // The first collision of the way back (the review lists them all).
    sphere(scene_->collision, !marks.collisions.empty(),
           marks.collisions.empty() ? std::array<double, 3>{} : marks.collisions.front(),
           QColor(0xd0, 0x00, 0x00));
    scene_->repos->SetVisibility(marks.hasRepos);
    if (marks.hasRepos) {
        vtkNew<vtkPolyLineSource> line;  // the corners of ADJUST / REPOS (TP-007)
        line->SetNumberOfPoints(static_cast<vtkIdType>(marks.repos.size()));
        for (std::size_t i = 0; i < marks.repos.size(); ++i)
            line->SetPoint(static_cast<vtkIdType>(i), marks.repos[i][0], marks.repos[i][1],
                           marks.repos[i][2]);
        line->Update();
        vtkNew<vtkPolyDataMapper> mapper;
        mapper->SetInputData(line->GetOutput());
        scene_->repos->SetMapper(mapper);
        setColour(scene_->repos->GetProperty(), palette.repos);
    }
    return true;
}

QImage VtkToolpathCanvas::picture() {
    renderNow();
    return widget_->grabFramebuffer();
}

std::optional<QPoint> VtkToolpathCanvas::positionOfMove(long move) {
    const auto g = model_->geometry();
    if (!g || move < 0 || static_cast<std::size_t>(move) >= g->moves.size()) return std::nullopt;
    const auto m = static_cast<std::size_t>(move);
    const bool inScene = g->sceneRange(m).first < g->sceneRange(m).second;
    if (!inScene && !scene_->split) return std::nullopt;
    Part& part = inScene ? scene_->scene : scene_->developed;
    const auto& layer = inScene ? g->scene : g->developed;
    const auto [first, last] = inScene ? g->sceneRange(m) : g->developedRange(m);
    if (first == last) return std::nullopt;
    const auto a = layer.vertex(layer.segmentStart[first]);
    const auto b = layer.vertex(layer.segmentStart[first] + 1);
    part.renderer->SetWorldPoint((a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2, 1.0);
    part.renderer->WorldToDisplay();
    double display[3];
    part.renderer->GetDisplayPoint(display);
    const double ratio = widget_->devicePixelRatioF();
    const int height = static_cast<int>(widget_->height() * ratio);
    if (!part.renderer->IsInViewport(static_cast<int>(display[0]), static_cast<int>(display[1])))
        return std::nullopt;
    const QPoint inWidget(static_cast<int>(display[0] / ratio),
                          static_cast<int>((height - 1 - display[1]) / ratio));
    return widget_->mapTo(this, inWidget);
}

void VtkToolpathCanvas::pickAt(QPoint position) {
    const auto g = model_->geometry();
    if (!g) return;
    const double ratio = widget_->devicePixelRatioF();
    const int x = static_cast<int>(position.x() * ratio);
    const int y =
        static_cast<int>(widget_->height() * ratio) - 1 - static_cast<int>(position.y() * ratio);
    for (Part* part : {&scene_->scene, &scene_->developed}) {
        if (!part->full || !part->renderer->IsInViewport(x, y)) continue;
        // The full segment nearest on the screen, found through the coarse
        // copy's cells (TP-010): right whichever copy is shown.
        mtc::core::ScreenProjection view;
        vtkMatrix4x4* toNdc =
            part->renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
                part->renderer->GetTiledAspectRatio(), -1, 1);
        for (int i = 0; i < 16; ++i)
            view.toNdc[static_cast<std::size_t>(i)] = toNdc->GetElement(i / 4, i % 4);
        const int* origin = part->renderer->GetOrigin();
        const int* size = part->renderer->GetSize();
        view.originX = origin[0];
        view.originY = origin[1];
        view.width = size[0];
        view.height = size[1];
        const auto picked =
            mtc::core::pickSegment(part->developed ? g->developed : g->scene, part->decimated, view,
                                   x, y, kPickPixels * ratio);
        if (!picked) continue;
        if (part->decimated.cellCount() > 0) ++scene_->coarsePicks;
        const std::uint32_t segment = *picked;
        const long move =
            part->developed ? g->moveOfDevelopedSegment(segment) : g->moveOfSceneSegment(segment);
        if (move >= 0) model_->pick(move);
        return;
    }
}

bool VtkToolpathCanvas::eventFilter(QObject* watched, QEvent* event) {
    if (watched == widget_ && event->type() == QEvent::MouseButtonPress) {
        scene_->pressed = static_cast<QMouseEvent*>(event)->pos();
    } else if (watched == widget_ && event->type() == QEvent::MouseButtonRelease) {
        const auto* mouse = static_cast<QMouseEvent*>(event);
        if (mouse->button() == Qt::LeftButton &&
            (mouse->pos() - scene_->pressed).manhattanLength() < 4)
            pickAt(mouse->pos());
    }
    return ToolpathCanvas::eventFilter(watched, event);
}

}  // namespace mtc::screens
