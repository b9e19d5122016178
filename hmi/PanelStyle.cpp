#include "hmi/PanelStyle.h"

namespace mtc::hmi {

QString panelStyleSheet() {
    return QStringLiteral(R"(
QMainWindow#panelWindow { background: #c8c8c8; }
QWidget#statusHeader { background: #00307a; }
QWidget#statusHeader QLabel { color: white; }
QLabel#headerAlarm { color: #ffd000; }
QWidget#softKeyBar QPushButton, QWidget#machineKeyBar QPushButton {
    background: qlineargradient(x1:0, y1:0, x2:0, y2:1, stop:0 #f4f4f4, stop:1 #b8b8b8);
    border: 2px outset #e0e0e0; border-radius: 3px; padding: 0px; color: black;
}
QWidget#softKeyBar QPushButton:pressed, QWidget#machineKeyBar QPushButton:pressed {
    border-style: inset;
}
QWidget#softKeyBar QPushButton:disabled { color: #8a8a8a; }
QWidget#machineKeyBar QPushButton { background: #dfe6ef; }
QWidget#machineKeyBar QPushButton[lamp="true"] {
    background: #ffd34d; border: 2px solid #b07800; font-weight: bold;
}
QAbstractItemView, QPlainTextEdit, QTextBrowser { background: white; selection-background-color: #00307a; }
)");
}

}  // namespace mtc::hmi
