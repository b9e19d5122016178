#include "screens/toolpath/VtkToolpathPart.h"

#include <vtkCamera.h>

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

CameraPose poseOf(vtkCamera& camera) {
    CameraPose pose;
    camera.GetDirectionOfProjection(pose.direction.data());
    camera.GetViewUp(pose.up.data());
    return pose;
}

void Part::setScreenScale(double scale) {
    screenScale = scale;
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

namespace {

/// Where a box lies on a parallel camera's screen, in world units from the
/// focal point along the screen's up: lowest and highest, and the lowest
/// of its edges left of `right` (along the screen's right).
struct ScreenExtent {
    double low = 0.0, high = 0.0;
    double lowOverCaption = 1e300;
};

ScreenExtent screenExtent(const mtc::core::ToolpathBounds& box, vtkCamera& camera, double right) {
    const CameraPose pose = poseOf(camera);
    const std::array<double, 3>& up = pose.up;
    const std::array<double, 3> side = pose.right();
    double focal[3];
    camera.GetFocalPoint(focal);
    double x[8], y[8];
    for (int corner = 0; corner < 8; ++corner) {
        x[corner] = y[corner] = 0.0;
        for (std::size_t k = 0; k < 3; ++k) {
            const double at = ((corner >> k) & 1 ? box.max[k] : box.min[k]) - focal[k];
            x[corner] += at * side[k];
            y[corner] += at * up[k];
        }
    }
    ScreenExtent extent{*std::min_element(y, y + 8), *std::max_element(y, y + 8)};
    // The 12 edges, each cut at `right`: its lowest point left of it.
    for (int a = 0; a < 8; ++a) {
        for (int k = 0; k < 3; ++k) {
            if ((a >> k) & 1) continue;
            const int b = a | (1 << k);
            if (x[a] <= right) extent.lowOverCaption = std::min(extent.lowOverCaption, y[a]);
            if (x[b] <= right) extent.lowOverCaption = std::min(extent.lowOverCaption, y[b]);
            if ((x[a] <= right) != (x[b] <= right)) {
                const double t = (right - x[a]) / (x[b] - x[a]);
                extent.lowOverCaption = std::min(extent.lowOverCaption, y[a] + t * (y[b] - y[a]));
            }
        }
    }
    return extent;
}

}  // namespace

bool Part::fitCaptionToWidth() {
    const int width = renderer->GetSize()[0];
    const char* input = caption->GetInput();
    const char* text = input ? input : "";
    CaptionFit& last = captionFittedFor;
    if (width <= 0 || (width == last.width && screenScale == last.scale && last.text == text))
        return false;
    last = {text, width, screenScale};
    vtkTextProperty* font = caption->GetTextProperty();
    const int before = font->GetFontSize();
    const int nominal = static_cast<int>(std::lround(kCaptionSize * screenScale));
    font->SetFontSize(nominal);
    double box[4];  // x min, x max, y min, y max
    caption->GetBoundingBox(renderer, box);
    const double room = width - 2.0 * kCaptionMargin * screenScale;
    const double used = box[1] - box[0];
    if (used > room && room > 0.0)
        font->SetFontSize(std::max(8, static_cast<int>(std::floor(nominal * room / used))));
    return font->GetFontSize() != before;
}

void Part::frame(const mtc::core::ToolpathBounds& box) {
    if (box.empty) {
        renderer->ResetCamera();
    } else {
        double bounds[6] = {box.min[0], box.max[0], box.min[1], box.max[1], box.min[2], box.max[2]};
        renderer->ResetCamera(bounds);
        keepClearOfCaption(box);
    }
    fitClippingRange();
}

void Part::keepClearOfCaption(const mtc::core::ToolpathBounds& box) {
    vtkCamera* camera = renderer->GetActiveCamera();
    const int* size = renderer->GetSize();
    if (!camera->GetParallelProjection() || size[0] <= 0 || size[1] <= 0) return;
    // The caption's box, and room for the tick labels and title the axes
    // hang beside the box: device pixels, as shares of the view.
    double text[4];  // x min, x max, y min, y max
    caption->GetBoundingBox(renderer, text);
    const double labelPixels =
        ((kAxesTextOffset + kAxesTextSize) * 2 + kCaptionMargin) * screenScale;
    const double below = std::min(0.45, (text[3] + labelPixels) / size[1]);
    const double beside = std::min(1.0, (text[1] + labelPixels) / size[0]);
    camera->OrthogonalizeViewUp();
    double scale = camera->GetParallelScale();  // half the view's height
    const double halfWidth = scale * size[0] / size[1];
    const ScreenExtent extent = screenExtent(box, *camera, -halfWidth + 2.0 * beside * halfWidth);
    const double lowest = -scale * (1.0 - 2.0 * below);  // where the free part begins
    if (extent.lowOverCaption >= lowest) return;         // already clear
    // Up just far enough; if the top would leave the view, zoomed out to
    // the free part's height and centred in it. The zoom-out lifts the whole
    // part over the caption's band, not only what lies beside the caption:
    // it may leave more room than needed, but it never covers (TP-031).
    double shift = extent.lowOverCaption - lowest;  // the camera's move along up
    if (extent.high - shift > scale) {
        scale = (extent.high - extent.low) / (2.0 * (1.0 - below));
        shift = (extent.high + extent.low) / 2.0 - below * scale;
    }
    double up[3], focal[3], position[3];
    camera->GetViewUp(up);
    camera->GetFocalPoint(focal);
    camera->GetPosition(position);
    for (int k = 0; k < 3; ++k) {
        focal[k] += shift * up[k];
        position[k] += shift * up[k];
    }
    camera->SetFocalPoint(focal);
    camera->SetPosition(position);
    camera->SetParallelScale(scale);
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
