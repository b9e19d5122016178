#include "screens/toolpath/VtkToolpathPart.h"

#include <algorithm>
#include <cmath>

namespace mtc::screens {

void Part::setUp(const ToolpathPalette& palette) {
    const QColor& bg = palette.background;
    renderer->SetBackground(bg.redF(), bg.greenF(), bg.blueF());
    for (auto [m, actor] :
         {std::pair{mapper.Get(), path.Get()}, std::pair{coarseMapper.Get(), coarsePath.Get()}}) {
        m->SetScalarModeToUsePointData();
        m->SetColorModeToDirectScalars();
        actor->SetMapper(m);
        actor->GetProperty()->SetLighting(false);
    }
    coarsePath->VisibilityOff();
    contourMapper->ScalarVisibilityOff();
    contour->SetMapper(contourMapper);
    contour->GetProperty()->SetLighting(false);
    setColour(contour->GetProperty(), palette.contour);
    contour->PickableOff();
    contour->VisibilityOff();
    highlightMapper->ScalarVisibilityOff();
    highlight->SetMapper(highlightMapper);
    highlight->GetProperty()->SetLighting(false);
    setColour(highlight->GetProperty(), palette.highlight);
    highlight->PickableOff();
    axes->SetCamera(renderer->GetActiveCamera());
    axes->DrawXGridlinesOn();
    axes->DrawYGridlinesOn();
    axes->DrawZGridlinesOn();
    axes->SetGridLineLocation(vtkCubeAxesActor::VTK_GRID_LINES_FURTHEST);
    // One labelled edge per axis, the one nearest the viewer: labels on
    // several edges ran into each other and were drawn twice in the plane
    // views, where front and back edges coincide (TP-014).
    axes->SetFlyModeToClosestTriad();
    for (int i = 0; i < 3; ++i) {
        setColour(axes->GetTitleTextProperty(i), QColor(220, 220, 230));
        setColour(axes->GetLabelTextProperty(i), QColor(200, 200, 210));
    }
    setColour(axes->GetXAxesGridlinesProperty(), palette.grid);
    setColour(axes->GetYAxesGridlinesProperty(), palette.grid);
    setColour(axes->GetZAxesGridlinesProperty(), palette.grid);
    axes->PickableOff();
    caption->GetTextProperty()->SetColor(1, 1, 1);
    renderer->AddActor(contour);
    renderer->AddActor(path);
    renderer->AddActor(coarsePath);
    live->AddActor(highlight);
    renderer->AddActor(axes);
    renderer->AddActor2D(caption);
    backplot = std::make_unique<VtkBackplot>(renderer, live, palette.backplot);
    setScreenScale(1.0);
}

void Part::setScreenScale(double scale) {
    const auto width = [scale](double w) {
        return static_cast<float>(ToolpathCanvas::scaledWidth(w, scale));
    };
    // VTK's text sizes are device pixels too: the caption and the axes'
    // labels grow with the lines (TP-026).
    caption->GetTextProperty()->SetFontSize(static_cast<int>(std::lround(kCaptionSize * scale)));
    caption->SetPosition(kCaptionMargin * scale, kCaptionMargin * scale);
    axes->SetScreenSize(kAxesTextSize * scale);
    axes->SetLabelOffset(kAxesTextOffset * scale);
    axes->SetTitleOffset(kAxesTextOffset * scale);
    path->GetProperty()->SetLineWidth(width(kPathWidth));
    coarsePath->GetProperty()->SetLineWidth(width(kPathWidth));
    contour->GetProperty()->SetLineWidth(width(kContourWidth));
    highlight->GetProperty()->SetLineWidth(width(kHighlightWidth));
    backplot->setWidth(width(VtkBackplot::kWidth));
}

void Part::fitClippingRange() {
    double a[6], b[6];  // steady, live
    renderer->ComputeVisiblePropBounds(a);
    live->ComputeVisiblePropBounds(b);
    double box[6];
    for (int i = 0; i < 3; ++i) {
        const bool hasA = a[2 * i] <= a[2 * i + 1], hasB = b[2 * i] <= b[2 * i + 1];
        if (!hasA && !hasB) return renderer->ResetCameraClippingRange();
        box[2 * i] = !hasB ? a[2 * i] : !hasA ? b[2 * i] : std::min(a[2 * i], b[2 * i]);
        box[2 * i + 1] = !hasB   ? a[2 * i + 1]
                         : !hasA ? b[2 * i + 1]
                                 : std::max(a[2 * i + 1], b[2 * i + 1]);
    }
    const double spare = 0.5 * std::max({box[1] - box[0], box[3] - box[2], box[5] - box[4], 1.0});
    for (int i = 0; i < 3; ++i) {
        box[2 * i] -= spare;
        box[2 * i + 1] += spare;
    }
    renderer->ResetCameraClippingRange(box);
}

}  // namespace mtc::screens
