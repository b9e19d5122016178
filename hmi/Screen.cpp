#include "hmi/Screen.h"

namespace mtc::hmi {

Screen::Screen(const ScreenContext& context, QWidget* parent) : QWidget(parent), context_(context) {
    setFocusPolicy(Qt::StrongFocus);
}

}  // namespace mtc::hmi
