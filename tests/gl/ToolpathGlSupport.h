#pragma once

// Helpers of the toolpath view's tests on a real X server (tests/gl).
#include <QColor>
#include <QImage>
#include <cmath>

#include "PanelFixture.h"
#include "screens/toolpath/ToolpathScreen.h"
#include "screens/toolpath/VtkToolpathCanvas.h"

inline mtc::screens::ToolpathScreen* toolpath(PanelFixture& panel, int slot = 0) {
    return static_cast<mtc::screens::ToolpathScreen*>(panel.window->screen(slot, "toolpath"));
}

/// Pixels within 40 (sum of channel differences) of `colour`.
inline int count(const QImage& image, const QColor& colour) {
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    int n = 0;
    for (int y = 0; y < rgb.height(); ++y)
        for (int x = 0; x < rgb.width(); ++x) {
            const QColor c(rgb.pixel(x, y));
            if (std::abs(c.red() - colour.red()) + std::abs(c.green() - colour.green()) +
                    std::abs(c.blue() - colour.blue()) <
                40)
                ++n;
        }
    return n;
}

inline mtc::screens::VtkToolpathCanvas* vtkCanvas(mtc::screens::ToolpathScreen* screen) {
    return qobject_cast<mtc::screens::VtkToolpathCanvas*>(screen->canvas());
}

/// Selects program `number` of the first station, shows the toolpath screen
/// and returns it; `canvas` is its VTK view (nullptr when the screen could
/// not be shown or has no 3D view).
inline mtc::screens::ToolpathScreen* showToolpathOf(PanelFixture& panel, int number,
                                                    mtc::screens::VtkToolpathCanvas*& canvas) {
    panel.session->selectProgram(0, number);
    canvas = nullptr;
    if (!panel.window->showScreen("toolpath")) return nullptr;
    mtc::screens::ToolpathScreen* screen = toolpath(panel);
    canvas = vtkCanvas(screen);
    return screen;
}
