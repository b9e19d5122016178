#pragma once

#include <QString>
#include <QVector>
#include <functional>

namespace mtc::hmi {

/// One soft key F1..F8 of a screen: its label and what it does.
struct SoftKey {
    QString label;                 ///< may contain '\n' for two lines
    std::function<void()> action;  ///< empty = key shown but without function
    bool enabled = true;
};

/// The eight soft keys of a screen; index 0 = F1. Missing keys are blank.
using SoftKeys = QVector<SoftKey>;

}  // namespace mtc::hmi
