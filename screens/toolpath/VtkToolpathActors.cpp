#include "screens/toolpath/VtkToolpathActors.h"

#include <vtkActor.h>
#include <vtkCubeAxesActor.h>
#include <vtkCylinderSource.h>
#include <vtkNew.h>
#include <vtkPolyDataMapper.h>
#include <vtkSphereSource.h>

#include <algorithm>

#include "screens/toolpath/ToolpathModel.h"

namespace mtc::screens {

void setBounds(vtkCubeAxesActor* axes, const mtc::core::ToolpathBounds& b) {
    double bounds[6] = {b.min[0], b.max[0], b.min[1], b.max[1], b.min[2], b.max[2]};
    axes->SetBounds(bounds);
}

void labelLongAxesOnly(vtkCubeAxesActor* axes, const mtc::core::ToolpathBounds& b) {
    const double longest = std::max(b.size(), 1e-9);
    const auto labelled = [&](int i) {
        return b.max[static_cast<std::size_t>(i)] - b.min[static_cast<std::size_t>(i)] >=
               0.2 * longest;
    };
    axes->SetXAxisLabelVisibility(labelled(0));
    axes->SetYAxisLabelVisibility(labelled(1));
    axes->SetZAxisLabelVisibility(labelled(2));
}

void placeCylinder(vtkActor* actor, int axis, double radius, double from, double to) {
    vtkNew<vtkCylinderSource> source;
    source->SetRadius(radius);
    source->SetHeight(std::max(to - from, 1e-3));
    source->SetCenter(0, (from + to) / 2, 0);
    source->SetResolution(72);
    source->Update();
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(source->GetOutput());
    actor->SetMapper(mapper);
    actor->SetOrientation(0, 0, 0);
    if (axis == 2) actor->RotateX(90);   // Y -> Z
    if (axis == 0) actor->RotateZ(-90);  // Y -> X
    actor->VisibilityOn();
}

void placeTool(vtkActor* actor, const ToolpathMarks& marks, double pictureSize) {
    actor->SetVisibility(marks.hasTool);
    if (!marks.hasTool) return;
    const double radius = std::max(marks.toolRadius, pictureSize * 0.01);
    if (marks.turning) {
        vtkNew<vtkSphereSource> source;
        source->SetRadius(radius);
        source->Update();
        vtkNew<vtkPolyDataMapper> mapper;
        mapper->SetInputData(source->GetOutput());
        actor->SetMapper(mapper);
        actor->SetOrientation(0, 0, 0);
    } else {
        const double length = std::max(marks.toolLength, 4.0 * radius);
        placeCylinder(actor, 2, radius, 0.0, length);
    }
    actor->SetPosition(marks.tool[0], marks.tool[1], marks.tool[2]);
}

}  // namespace mtc::screens
