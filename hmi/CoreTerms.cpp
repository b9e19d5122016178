#include "hmi/CoreTerms.h"

#include <QCoreApplication>

namespace mtc::hmi {

namespace {
// The core's names as lupdate sees them (the core has no Qt): the source
// texts of the context "CoreTerms". They must stay equal to the core's
// keyName(), modeName() and programStateWord(); the test
// `test_translations` checks every value of those enums against the catalogue.
[[maybe_unused]] const char* const kCoreTerms[] = {
    // machine control keys (keyName)
    QT_TRANSLATE_NOOP("CoreTerms", "NC program restart"),
    QT_TRANSLATE_NOOP("CoreTerms", "REPOS"),
    QT_TRANSLATE_NOOP("CoreTerms", "Manual"),
    QT_TRANSLATE_NOOP("CoreTerms", "Automatic"),
    QT_TRANSLATE_NOOP("CoreTerms", "Start"),
    QT_TRANSLATE_NOOP("CoreTerms", "Stop"),
    QT_TRANSLATE_NOOP("CoreTerms", "Control reset"),
    QT_TRANSLATE_NOOP("CoreTerms", "Single block"),
    QT_TRANSLATE_NOOP("CoreTerms", "MDI"),
    // operating modes (modeName)
    QT_TRANSLATE_NOOP("CoreTerms", "automatic"),
    QT_TRANSLATE_NOOP("CoreTerms", "manual"),
    // program states (programStateWord)
    QT_TRANSLATE_NOOP("CoreTerms", "running"),
    QT_TRANSLATE_NOOP("CoreTerms", "feed hold"),
    QT_TRANSLATE_NOOP("CoreTerms", "M00 stop"),
    QT_TRANSLATE_NOOP("CoreTerms", "single block"),
    QT_TRANSLATE_NOOP("CoreTerms", "waiting"),
    QT_TRANSLATE_NOOP("CoreTerms", "restart"),
    QT_TRANSLATE_NOOP("CoreTerms", "error"),
    // program states in full (programStateName)
    QT_TRANSLATE_NOOP("CoreTerms", "no program selected"),
    QT_TRANSLATE_NOOP("CoreTerms", "ready: Start runs the program"),
    QT_TRANSLATE_NOOP("CoreTerms", "feed hold: Start continues"),
    QT_TRANSLATE_NOOP("CoreTerms", "programmed stop (M00/M01): Start continues"),
    QT_TRANSLATE_NOOP("CoreTerms", "single block: Start runs the next block"),
    QT_TRANSLATE_NOOP("CoreTerms", "waiting for an axis (GAX)"),
    QT_TRANSLATE_NOOP("CoreTerms", "NC program restart: waiting for the SPS"),
    QT_TRANSLATE_NOOP("CoreTerms", "NC program restart active"),
    QT_TRANSLATE_NOOP("CoreTerms", "stopped by an error"),
    // spindle turn (spindleTurnName)
    QT_TRANSLATE_NOOP("CoreTerms", "CW (M3)"),
    QT_TRANSLATE_NOOP("CoreTerms", "CCW (M4)"),
    QT_TRANSLATE_NOOP("CoreTerms", "stopped (M5)"),
    QT_TRANSLATE_NOOP("CoreTerms", "oriented (M19)"),
    // G function groups, brief names (gGroupName(group).brief)
    QT_TRANSLATE_NOOP("CoreTerms", "interpolation"),
    QT_TRANSLATE_NOOP("CoreTerms", "plane"),
    QT_TRANSLATE_NOOP("CoreTerms", "radius comp."),
    QT_TRANSLATE_NOOP("CoreTerms", "zero offset"),
    QT_TRANSLATE_NOOP("CoreTerms", "feed type"),
    QT_TRANSLATE_NOOP("CoreTerms", "dimensions"),
    QT_TRANSLATE_NOOP("CoreTerms", "radius/diameter"),
    QT_TRANSLATE_NOOP("CoreTerms", "units"),
    QT_TRANSLATE_NOOP("CoreTerms", "spindle speed"),
    QT_TRANSLATE_NOOP("CoreTerms", "acceleration"),
    QT_TRANSLATE_NOOP("CoreTerms", "exact stop"),
    QT_TRANSLATE_NOOP("CoreTerms", "length comp."),
    QT_TRANSLATE_NOOP("CoreTerms", "transformation"),
};
}  // namespace

QString coreTerm(const char* english) {
    if (english == nullptr || *english == '\0') return {};
    return QCoreApplication::translate("CoreTerms", english);
}

QString keyLabel(mtc::core::ControlKey key) {
    return coreTerm(mtc::core::keyName(key));
}

QString modeLabel(mtc::core::OperatingMode mode) {
    return coreTerm(mtc::core::modeName(mode));
}

QString programStateLabel(mtc::core::ProgramState state) {
    return coreTerm(mtc::core::programStateWord(state));
}

QString programStateDescription(mtc::core::ProgramState state) {
    return coreTerm(mtc::core::programStateName(state));
}

}  // namespace mtc::hmi
