#include "screens/toolpath/VtkToolpathCache.h"

#include <algorithm>

#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkRendererCollection.h>
#include <vtkUnsignedCharArray.h>

namespace mtc::screens {

VtkStillCache::VtkStillCache(vtkRenderWindow* window) : window_(window) {
    if (window_->GetNumberOfLayers() < 2) window_->SetNumberOfLayers(2);
    vtkNew<vtkCallbackCommand> check;
    check->SetClientData(this);
    check->SetCallback([](vtkObject*, unsigned long, void* self, void*) {
        static_cast<VtkStillCache*>(self)->beforeRender();
    });
    observer_ = window_->AddObserver(vtkCommand::StartEvent, check);
}

VtkStillCache::~VtkStillCache() {
    window_->RemoveObserver(observer_);
}

void VtkStillCache::addArea(vtkRenderer* steady, vtkRenderer* live) {
    live->SetLayer(1);
    live->SetActiveCamera(steady->GetActiveCamera());
    live->InteractiveOff();
    areas_.push_back({steady, live, nullptr});
}

void VtkStillCache::setEnabled(bool enabled) {
    enabled_ = enabled;
    if (!enabled_) drop();
}

void VtkStillCache::invalidate() {
    drop();
}

std::vector<double> VtkStillCache::key() const {
    std::vector<double> key;
    const int* size = window_->GetSize();
    key.push_back(size[0]);
    key.push_back(size[1]);
    for (const Area& area : areas_) {
        key.push_back(window_->HasRenderer(area.steady) ? 1.0 : 0.0);
        const double* viewport = area.steady->GetViewport();
        key.insert(key.end(), viewport, viewport + 4);
        vtkCamera* camera = area.steady->GetActiveCamera();
        for (const double* v : {camera->GetPosition(), camera->GetFocalPoint(), camera->GetViewUp(),
                                camera->GetClippingRange()})
            key.insert(key.end(), v, v + (v == camera->GetClippingRange() ? 2 : 3));
        key.push_back(camera->GetParallelScale());
        key.push_back(camera->GetParallelProjection());
    }
    return key;
}

void VtkStillCache::beforeRender() {
    if (keeping_ && !capturing_ && key() != lastKey_) invalidate();
}

void VtkStillCache::drop() {
    if (!keeping_) return;
    keeping_ = false;
    for (Area& area : areas_) {
        area.steady->DrawOn();
        area.live->SetPreserveColorBuffer(1);
        area.live->TexturedBackgroundOff();
        area.live->SetBackgroundTexture(nullptr);
        area.picture = nullptr;
    }
}

bool VtkStillCache::keep() {
    // The steady renderers alone: the live ones and any other (the axes
    // triad's) draw over the kept image each frame; drawn into it as well,
    // their anti-aliased edges would blend twice.
    std::vector<vtkRenderer*> others;
    vtkRendererCollection* renderers = window_->GetRenderers();
    renderers->InitTraversal();
    while (vtkRenderer* r = renderers->GetNextItem()) {
        const bool steady = std::any_of(areas_.begin(), areas_.end(),
                                        [r](const Area& area) { return area.steady == r; });
        if (!steady && r->GetDraw()) {
            others.push_back(r);
            r->DrawOff();
        }
    }
    capturing_ = true;
    window_->Render();
    capturing_ = false;
    for (vtkRenderer* r : others)
        r->DrawOn();
    for (Area& area : areas_) {
        if (!window_->HasRenderer(area.steady)) continue;
        const int* origin = area.steady->GetOrigin();
        const int* size = area.steady->GetSize();
        if (size[0] <= 0 || size[1] <= 0) return false;
        vtkNew<vtkUnsignedCharArray> pixels;
        // RGB: the framebuffer's alpha is 0 where the background is, and the
        // background texture is blended with it.
        if (window_->GetPixelData(origin[0], origin[1], origin[0] + size[0] - 1,
                                  origin[1] + size[1] - 1, 0, pixels) != 1)
            return false;
        vtkNew<vtkImageData> image;
        image->SetDimensions(size[0], size[1], 1);
        image->GetPointData()->SetScalars(pixels);
        area.picture = vtkSmartPointer<vtkTexture>::New();
        area.picture->SetInputData(image);
        area.picture->InterpolateOff();
    }
    for (Area& area : areas_) {
        if (!area.picture) continue;
        area.steady->DrawOff();
        area.live->SetPreserveColorBuffer(0);
        area.live->SetBackgroundTexture(area.picture);
        area.live->TexturedBackgroundOn();
    }
    keeping_ = true;
    ++pictures_;
    return true;
}

void VtkStillCache::render(bool mayKeep) {
    const std::vector<double> now = key();
    if (keeping_ && now != lastKey_) drop();
    // A steady picture that changed is kept at once when the cameras stand
    // (TP-029): drawing it in full first and keeping it at the next render
    // drew it twice - on llvmpipe twice the part's mesh each time the live
    // part changed. While the cameras move, nothing is kept.
    if (!keeping_ && mayKeep && enabled_ && !unreadable_ && now == lastKey_ && !keep())
        unreadable_ = true;
    lastKey_ = now;
    window_->Render();
    if (keeping_) ++kept_;
}

}  // namespace mtc::screens
