#include "screens/toolpath/VtkToolpathActors.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCubeAxesActor.h>
#include <vtkCylinderSource.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>

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
    axes->SetXAxisRange(frame.workpiece(0, b[0]), frame.workpiece(0, b[1]));
    axes->SetYAxisRange(frame.workpiece(1, b[2]), frame.workpiece(1, b[3]));
    axes->SetZAxisRange(frame.workpiece(2, b[4]), frame.workpiece(2, b[5]));
    axes->SetXTitle(titles[0].c_str());
    axes->SetYTitle(titles[1].c_str());
    axes->SetZTitle(titles[2].c_str());
}

void placeFinishedPart(vtkActor* actor, const std::vector<float>& triangles, const QColor& colour,
                       bool shadeByHeight) {
    const auto corners = static_cast<vtkIdType>(triangles.size() / 3);
    vtkNew<vtkFloatArray> xyz;
    xyz->SetNumberOfComponents(3);
    xyz->SetNumberOfTuples(corners);
    std::copy(triangles.begin(), triangles.begin() + 3 * corners, xyz->GetPointer(0));
    vtkNew<vtkPoints> points;
    points->SetData(xyz);
    vtkNew<vtkCellArray> cells;
    cells->AllocateExact(corners / 3, corners);
    for (vtkIdType t = 0; t + 2 < corners; t += 3) {
        const vtkIdType ids[3] = {t, t + 1, t + 2};
        cells->InsertNextCell(3, ids);
    }
    vtkNew<vtkPolyData> surface;
    surface->SetPoints(points);
    surface->SetPolys(cells);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(surface);
    mapper->ScalarVisibilityOff();
    // The tool centre runs on the cut surface (a flat end mill's tip on the
    // floor): the surface steps back in depth so the path stays on top.
    vtkMapper::SetResolveCoincidentTopologyToPolygonOffset();  // VTK's default is off
    mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(4.0, 16.0);
    if (shadeByHeight && corners > 0) {
        // Every floor of a z-map faces up and takes the same light: darker
        // with depth, so a pocket reads as a pocket from any side.
        float zMin = triangles[2], zMax = triangles[2];
        for (vtkIdType i = 0; i < corners; ++i) {
            zMin = std::min(zMin, triangles[static_cast<std::size_t>(3 * i + 2)]);
            zMax = std::max(zMax, triangles[static_cast<std::size_t>(3 * i + 2)]);
        }
        vtkNew<vtkUnsignedCharArray> rgb;
        rgb->SetNumberOfComponents(3);
        rgb->SetNumberOfTuples(corners);
        const float span = zMax > zMin ? zMax - zMin : 1.0f;
        for (vtkIdType i = 0; i < corners; ++i) {
            const float share = (triangles[static_cast<std::size_t>(3 * i + 2)] - zMin) / span;
            const float shade = 0.45f + 0.55f * share;
            unsigned char* c = rgb->GetPointer(3 * i);
            c[0] = static_cast<unsigned char>(colour.red() * shade);
            c[1] = static_cast<unsigned char>(colour.green() * shade);
            c[2] = static_cast<unsigned char>(colour.blue() * shade);
        }
        surface->GetPointData()->SetScalars(rgb);
        mapper->ScalarVisibilityOn();
        mapper->SetColorModeToDirectScalars();
    }
    actor->SetMapper(mapper);
    vtkProperty* p = actor->GetProperty();
    p->SetColor(colour.redF(), colour.greenF(), colour.blueF());
    p->SetInterpolationToFlat();
    p->SetAmbient(0.35);
    p->SetDiffuse(0.65);
    p->SetOpacity(1.0);
    p->LightingOn();
}

std::array<double, 2> axisRange(vtkCubeAxesActor* axes, int axis) {
    const double* range = axis == 0   ? axes->GetXAxisRange()
                          : axis == 1 ? axes->GetYAxisRange()
                                      : axes->GetZAxisRange();
    return {range[0], range[1]};
}

QString axisTitleOf(vtkCubeAxesActor* axes, int axis) {
    return QString::fromUtf8(axis == 0   ? axes->GetXTitle()
                             : axis == 1 ? axes->GetYTitle()
                                         : axes->GetZTitle());
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
