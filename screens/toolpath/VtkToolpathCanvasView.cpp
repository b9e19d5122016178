// The VTK toolpath view's camera (presets, fit, zoom, pan, turn) and what
// the tests read of its picture (captions, boxes, ticks, titles).
#include <vtkCamera.h>
#include <vtkCubeAxesActor.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>

#include <QVTKOpenGLNativeWidget.h>
#include <QRectF>
#include <algorithm>
#include <cmath>

#include "screens/toolpath/VtkToolpathActors.h"
#include "screens/toolpath/VtkToolpathCanvas.h"
#include "screens/toolpath/VtkToolpathScene.h"

namespace mtc::screens {

QRect VtkToolpathCanvas::sceneCaptionRect() const {
    double box[4];  // x min, x max, y min, y max in its viewport's device pixels
    scene_->scene.caption->GetBoundingBox(scene_->scene.renderer, box);
    const int* origin = scene_->scene.renderer->GetOrigin();
    const double inWindow[4] = {box[0] + origin[0], box[1] + origin[0], box[2] + origin[1],
                                box[3] + origin[1]};
    return deviceToWidget(inWindow);
}

QRect VtkToolpathCanvas::framedRect() const {
    const mtc::core::ToolpathBounds box = model_->frame(false, false);
    if (box.empty) return {};
    double rect[4] = {1e300, -1e300, 1e300, -1e300};
    for (int corner = 0; corner < 8; ++corner) {
        const auto at = [&](std::size_t k) { return (corner >> k) & 1 ? box.max[k] : box.min[k]; };
        scene_->scene.renderer->SetWorldPoint(at(0), at(1), at(2), 1.0);
        scene_->scene.renderer->WorldToDisplay();
        const double* display = scene_->scene.renderer->GetDisplayPoint();
        rect[0] = std::min(rect[0], display[0]);
        rect[1] = std::max(rect[1], display[0]);
        rect[2] = std::min(rect[2], display[1]);
        rect[3] = std::max(rect[3], display[1]);
    }
    return deviceToWidget(rect);
}

QRect VtkToolpathCanvas::triadRect() const {
    const double* v = scene_->triad->GetViewport();
    const int* size = scene_->window->GetSize();
    const double box[4] = {v[0] * size[0], v[2] * size[0], v[1] * size[1], v[3] * size[1]};
    return deviceToWidget(box);
}

QRect VtkToolpathCanvas::deviceToWidget(const double box[4]) const {
    const double ratio = widget_->devicePixelRatioF();
    const int height = scene_->window->GetSize()[1];
    return QRectF(QPointF(box[0], height - box[3]) / ratio,
                  QPointF(box[1], height - box[2]) / ratio)
        .toAlignedRect();
}

QString VtkToolpathCanvas::sceneCaption() const {
    return QString::fromUtf8(scene_->scene.caption->GetInput());
}

std::array<double, 2> VtkToolpathCanvas::tickRange(int axis) const {
    return axisRange(scene_->scene.axes, axis);
}

QString VtkToolpathCanvas::axisTitle(int axis) const {
    return axisTitleOf(scene_->scene.axes, axis);
}

void VtkToolpathCanvas::showAxesFor(ToolpathPreset preset) {
    vtkCubeAxesActor* axes = scene_->scene.axes;
    axes->SetXAxisVisibility(preset != ToolpathPreset::G19);
    axes->SetYAxisVisibility(preset != ToolpathPreset::G18);
    axes->SetZAxisVisibility(preset != ToolpathPreset::G17);
}

void VtkToolpathCanvas::showPreset(ToolpathPreset preset) {
    scene_->preset = preset;
    showAxesFor(preset);
    const CameraPose pose = presetPose(preset);
    vtkCamera* camera = scene_->scene.renderer->GetActiveCamera();
    camera->SetFocalPoint(0, 0, 0);
    camera->SetPosition(-pose.direction[0], -pose.direction[1], -pose.direction[2]);
    camera->SetViewUp(pose.up[0], pose.up[1], pose.up[2]);
    camera->ParallelProjectionOn();
    vtkCamera* flat = scene_->developed.renderer->GetActiveCamera();
    flat->SetFocalPoint(0, 0, 0);
    flat->SetPosition(0, 0, 1);
    flat->SetViewUp(0, 1, 0);
    flat->ParallelProjectionOn();
    fit();
}

void VtkToolpathCanvas::fit() {
    frame(false);
}

void VtkToolpathCanvas::fitAll() {
    frame(true);
}

void VtkToolpathCanvas::frame(bool all) {
    for (Part* part : {&scene_->scene, &scene_->developed})
        part->frame(model_->frame(part->developed, all));
    scene_->refitWhenShown = widget_->isVisible() ? std::nullopt : std::optional<bool>(all);
    requestRender();
}

void VtkToolpathCanvas::zoom(double factor) {
    for (Part* part : {&scene_->scene, &scene_->developed}) {
        part->renderer->GetActiveCamera()->Zoom(factor);
        part->fitClippingRange();
    }
    moving();
    requestRender();
}

void VtkToolpathCanvas::pan(double right, double up) {
    for (Part* part : {&scene_->scene, &scene_->developed}) {
        vtkCamera* camera = part->renderer->GetActiveCamera();
        const double height = 2 * camera->GetParallelScale();
        const double width = height * std::max(part->renderer->GetTiledAspectRatio(), 1e-3);
        const CameraPose pose = poseOf(*camera);
        const std::array<double, 3> side = pose.right();
        const std::array<double, 3>& upVector = pose.up;
        double focal[3], position[3];
        camera->GetFocalPoint(focal);
        camera->GetPosition(position);
        for (int i = 0; i < 3; ++i) {
            const auto k = static_cast<std::size_t>(i);
            const double shift = -(right * width * side[k] + up * height * upVector[k]);
            focal[i] += shift;
            position[i] += shift;
        }
        camera->SetFocalPoint(focal);
        camera->SetPosition(position);
    }
    moving();
    requestRender();
}

void VtkToolpathCanvas::rotate(double azimuth, double elevation) {
    showAxesFor(ToolpathPreset::Isometric);  // out of the plane: all three
    vtkCamera* camera = scene_->scene.renderer->GetActiveCamera();
    camera->Azimuth(azimuth);
    camera->Elevation(elevation);
    camera->OrthogonalizeViewUp();
    scene_->scene.fitClippingRange();
    moving();
    requestRender();
}

}  // namespace mtc::screens
