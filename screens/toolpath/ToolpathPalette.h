#pragma once

#include <QColor>

#include "cnc_core/toolpath/ToolpathGeometry.h"

namespace mtc::screens {

/// Colours of the toolpath view (3D and 2D alike), so that tests can look
/// for them in the picture: motion types, the highlighted block, the marks
/// of the restart screen, the stock. Fully saturated and distinct on purpose.
struct ToolpathPalette {
    QColor rapid{255, 170, 0};      ///< G0: orange
    QColor feed{0, 200, 0};         ///< G1: green
    QColor arc{0, 160, 255};        ///< G2/G3: blue
    QColor highlight{255, 0, 255};  ///< the current block: magenta
    QColor start{255, 255, 0};      ///< start block of the restart: yellow
    QColor target{255, 40, 40};     ///< target block: red
    QColor reentry{255, 255, 255};  ///< re-entry point: white
    QColor repos{0, 255, 255};      ///< REPOS path: cyan
    QColor stock{150, 150, 170};    ///< stock (translucent)
    QColor background{26, 32, 44};  ///< view background (dark)
    QColor grid{70, 80, 100};       ///< grid and extents
    /// Programmed contour of compensated moves (the tool-centre path keeps
    /// the motion colours): lavender, drawn under the path.
    QColor contour{180, 120, 255};
    /// The tool where the axes are now (TP-015): pink.
    QColor tool{255, 128, 192};
    /// The backplot: what the running program has travelled since Start
    /// (TP-016), over the path: near white.
    QColor backplot{245, 245, 235};
    /// The finished part (TP-023): light brass, lit.
    QColor part{205, 185, 130};

    /// Colour of a move kind.
    QColor colour(mtc::core::ToolpathKind kind) const {
        switch (kind) {
            case mtc::core::ToolpathKind::Rapid:
                return rapid;
            case mtc::core::ToolpathKind::Feed:
                return feed;
            case mtc::core::ToolpathKind::Arc:
                return arc;
        }
        return feed;
    }
};

}  // namespace mtc::screens
