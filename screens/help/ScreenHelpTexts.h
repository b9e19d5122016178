#pragma once

#include <QString>
#include <vector>

namespace mtc::screens {

/// A key of a screen that is not one of its soft keys (they are listed from
/// the screen itself, as they are now).
struct HelpKey {
    const char* keys;     ///< "↑ / ↓", "Ctrl+S"
    const char* meaning;  ///< what it does
};

/// The context help of one screen (F12 on it, issue 20 §4): what it is for,
/// the seed section it reproduces, and its keys besides F1..F8.
struct ScreenHelpText {
    const char* screen;   ///< Screen::screenName()
    const char* purpose;  ///< what the screen is for, one paragraph
    const char* seed;     ///< "seed 001 ch. 9" or "" (the simulator's own)
    std::vector<HelpKey> keys;
};

/// The help of screen `name`, nullptr when it has none.
const ScreenHelpText* screenHelpText(const QString& name);
/// Every help text (a test checks each registered screen has one).
const std::vector<ScreenHelpText>& screenHelpTexts();

}  // namespace mtc::screens
