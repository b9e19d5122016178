#include "screens/toolpath/VtkToolpathActors.h"

#include <vtkActor.h>
#include <vtkCubeAxesActor.h>
#include <vtkCylinderSource.h>
#include <vtkNew.h>
#include <vtkPolyDataMapper.h>
#include <vtkSphereSource.h>

#include <algorithm>

#include "screens/toolpath/ToolpathModel.h"
#include "screens/toolpath/VtkToolpathCanvas.h"

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

QString extentsText(const mtc::core::ToolpathBounds& b, bool flat) {
    if (b.empty) return {};
    QString text = VtkToolpathCanvas::tr("extents %1 x %2")
                       .arg(b.max[0] - b.min[0], 0, 'f', 1)
                       .arg(b.max[1] - b.min[1], 0, 'f', 1);
    if (!flat) text += QString(" x %1").arg(b.max[2] - b.min[2], 0, 'f', 1);
    return text + " mm";
}

void labelInFrame(vtkCubeAxesActor* axes, const mtc::core::ToolpathFrame& frame,
                  const std::array<std::string, 3>& titles) {
    const double* b = axes->GetBounds();
    axes->SetXAxisRange(b[0] - frame.offset[0], b[1] - frame.offset[0]);
    axes->SetYAxisRange(b[2] - frame.offset[1], b[3] - frame.offset[1]);
    axes->SetZAxisRange(b[4] - frame.offset[2], b[5] - frame.offset[2]);
    axes->SetXTitle(titles[0].c_str());
    axes->SetYTitle(titles[1].c_str());
    axes->SetZTitle(titles[2].c_str());
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
