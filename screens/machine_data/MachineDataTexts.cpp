#include "screens/machine_data/MachineDataTexts.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace mtc::screens {

namespace {
constexpr const char* kContext = "MachineData";
}  // namespace

QString machineDataText(const std::string& name) {
    static const QRegularExpression kNumbered("^(.*\\S) ([0-9]+)$");
    const QRegularExpressionMatch numbered = kNumbered.match(QString::fromStdString(name));
    if (numbered.hasMatch()) {
        const QByteArray form = (numbered.captured(1) + " %1").toUtf8();
        const QString translated = QCoreApplication::translate(kContext, form.constData());
        if (translated != QString::fromUtf8(form)) return translated.arg(numbered.captured(2));
    }
    return QCoreApplication::translate(kContext, name.c_str());
}

const std::vector<const char*>& standardMachineDataTexts() {
    static const std::vector<const char*> kTexts = {
        // Page 30
        QT_TRANSLATE_NOOP("MachineData", "Adaptive feed control"),
        QT_TRANSLATE_NOOP("MachineData", "Adapt. feed control active"),
        QT_TRANSLATE_NOOP("MachineData", "Reference axis"),
        QT_TRANSLATE_NOOP("MachineData", "Amplification"),
        QT_TRANSLATE_NOOP("MachineData", "Measuring period idling torque"),
        QT_TRANSLATE_NOOP("MachineData", "Current idling torque"),
        QT_TRANSLATE_NOOP("MachineData", "Maximum idling torque"),
        QT_TRANSLATE_NOOP("MachineData", "Current machining torque"),
        QT_TRANSLATE_NOOP("MachineData", "Peak machining torque"),
        QT_TRANSLATE_NOOP("MachineData", "Minimum machining torque"),
        QT_TRANSLATE_NOOP("MachineData", "Limiting machining torque"),
        QT_TRANSLATE_NOOP("MachineData", "Current feed reduction"),
        QT_TRANSLATE_NOOP("MachineData", "Peak feed reduction"),
        QT_TRANSLATE_NOOP("MachineData", "Maximum feed reduction"),
        QT_TRANSLATE_NOOP("MachineData", "Stall torque"),
        // Page 60
        QT_TRANSLATE_NOOP("MachineData", "NC program restart and REPOS"),
        QT_TRANSLATE_NOOP("MachineData", "Rotary axis mode spindle %1"),
        QT_TRANSLATE_NOOP("MachineData", "Transformation selection"),
        QT_TRANSLATE_NOOP("MachineData", "T no. tool spindle %1"),
        // Page 61
        QT_TRANSLATE_NOOP("MachineData", "M(16) and Q function buffers"),
        QT_TRANSLATE_NOOP("MachineData", "M(16) functions"),
        QT_TRANSLATE_NOOP("MachineData", "Q functions"),
        QT_TRANSLATE_NOOP("MachineData", "Aux. Function %1"),
    };
    return kTexts;
}

}  // namespace mtc::screens
