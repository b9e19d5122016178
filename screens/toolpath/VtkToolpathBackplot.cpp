#include "screens/toolpath/VtkToolpathBackplot.h"

#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

#include "screens/toolpath/VtkToolpathData.h"

namespace mtc::screens {

VtkBackplot::VtkBackplot(vtkRenderer* steady, vtkRenderer* live, const QColor& colour)
    : steady_(steady), live_(live), colour_(colour), open_(newActor()) {
    open_->VisibilityOff();
    live_->AddActor(open_);
}

void VtkBackplot::setWidth(float width) {
    width_ = width;
    open_->GetProperty()->SetLineWidth(width);
    for (const auto& piece : sealed_)
        piece->GetProperty()->SetLineWidth(width);
}

VtkBackplot::~VtkBackplot() {
    clear();
    live_->RemoveActor(open_);
}

vtkSmartPointer<vtkActor> VtkBackplot::newActor() const {
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->ScalarVisibilityOff();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    vtkProperty* property = actor->GetProperty();
    property->SetColor(colour_.redF(), colour_.greenF(), colour_.blueF());
    property->SetLineWidth(width_);
    property->SetLighting(false);
    actor->PickableOff();
    return actor;
}

void VtkBackplot::clear() {
    for (const auto& piece : sealed_)
        steady_->RemoveActor(piece);
    sealed_.clear();
    sealedSegments_ = 0;
    open_->VisibilityOff();
    run_ = revision_ = 0;
    layer_ = nullptr;
}

void VtkBackplot::setSealedVisible(bool visible) {
    sealedVisible_ = visible;
    for (const auto& piece : sealed_)
        piece->SetVisibility(visible);
}

bool VtkBackplot::show(const ToolpathBackplot& backplot) {
    bool steadyChanged = false;
    if (backplot.empty() || backplot.run != run_ || backplot.layer != layer_ ||
        backplot.segments < sealedSegments_) {
        steadyChanged = !sealed_.empty() || open_->GetVisibility();
        clear();
    }
    if (backplot.empty()) return steadyChanged;
    if (backplot.revision == revision_ && open_->GetVisibility()) return steadyChanged;
    run_ = backplot.run;
    revision_ = backplot.revision;
    layer_ = backplot.layer;
    const mtc::core::ToolpathLayer& layer = *backplot.layer;
    while (backplot.segments - sealedSegments_ >= kPieceSegments) {
        vtkSmartPointer<vtkActor> piece = newActor();
        static_cast<vtkPolyDataMapper*>(piece->GetMapper())
            ->SetInputData(
                toolpathStretch(layer, sealedSegments_, sealedSegments_ + kPieceSegments, nullptr));
        piece->SetVisibility(sealedVisible_);
        steady_->AddActor(piece);
        sealed_.push_back(piece);
        sealedSegments_ += kPieceSegments;
        steadyChanged = true;
    }
    const std::array<std::array<double, 3>, 2> partial{backplot.partialFrom, backplot.partialTo};
    static_cast<vtkPolyDataMapper*>(open_->GetMapper())
        ->SetInputData(toolpathStretch(layer, sealedSegments_, backplot.segments,
                                       backplot.partial ? &partial : nullptr));
    open_->VisibilityOn();
    return steadyChanged;
}

}  // namespace mtc::screens
