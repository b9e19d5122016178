// German texts of the alarms, prompts and messages the core raises without a
// diagnostic: refusals of the machine control keys (docs/DECISIONS.md D-025),
// of jogging and the spindle keys, of Start, the GAX wait, the prompts of a
// held program and the MDI session's messages (D-026). "%1", "%2", ... are the
// values alarmText() fills in. Terms: docs/GLOSSARY.md.
#include "cnc_core/text/MessageTables.h"

namespace mtc::core::messages {

namespace {
constexpr MessageEntry kAlarmMessages[] = {
    // Machine control keys (D-025)
    {"ALARM_MDI_RESTART_ACTIVE", "MDI abgelehnt: Satzvorlauf aktiv (erst Steuerung rücksetzen)"},
    {"ALARM_MODE_PROGRAM_ACTIVE",
     "Betriebsartwechsel abgelehnt: ein Programm ist aktiv (erst Stop drücken)"},
    {"ALARM_MODE_RESTART_RUNNING",
     "Betriebsartwechsel abgelehnt: der Satzvorlauf läuft (erst Stop)"},
    {"ALARM_REPOS_NOT_YET",
     "REPOS abgelehnt: Wiederanfahren noch nicht möglich (PxxSREPOS = 0, der Rechenlauf hat "
     "den Zielsatz noch nicht erreicht)"},
    {"ALARM_REPOS_NO_RESTART",
     "REPOS abgelehnt: kein Wiederanfahren möglich (kein Satzvorlauf hat seinen Zielsatz "
     "erreicht)"},
    {"ALARM_SELECT_PROGRAM_ACTIVE", "Programmanwahl abgelehnt: ein Programm ist aktiv"},
    {"ALARM_START_NOT_AUTOMATIC", "Start abgelehnt: zuerst Automatik anwählen"},
    {"ALARM_START_NO_CORE", "Start abgelehnt: kein NC-Kern angeschlossen"},
    {"ALARM_START_NO_PROGRAM", "Start abgelehnt: kein Programm angewählt"},
    {"ALARM_START_NO_REPOS", "Start abgelehnt: Wiederanfahren (PxxCREPOS) nicht aktiv"},
    // Jogging and the spindle keys of manual mode (D-026)
    {"ALARM_JOG_AT_LIMIT", "%1 steht an der Verfahrgrenze"},
    {"ALARM_JOG_AXES_MOVING", "Die Achsen fahren noch"},
    {"ALARM_JOG_BRAKING", "Die Achse bremst noch"},
    {"ALARM_JOG_NO_AXIS", "Keine solche Achse zum Tippen"},
    {"ALARM_JOG_NO_DISTANCE", "Kein Tippweg"},
    {"ALARM_JOG_NOT_MANUAL", "Tippen nur im Handbetrieb (M-Taste Handbetrieb)"},
    {"ALARM_JOG_PROGRAM_ACTIVE", "Tippen abgelehnt: ein Programm ist aktiv"},
    {"ALARM_JOG_SPINDLE", "Eine Spindel wird nicht getippt; sie dreht mit M3/M4"},
    {"ALARM_JOG_TRAVEL_LIMIT",
     "Verfahrgrenze: %1 darf von %2 bis %3 fahren (Tippen nach %4 abgelehnt)"},
    {"ALARM_SPINDLE_NONE", "Keine solche Spindel"},
    {"ALARM_SPINDLE_NOT_MANUAL", "Spindeltasten nur im Handbetrieb (M-Taste Handbetrieb)"},
    {"ALARM_SPINDLE_PROGRAM_ACTIVE", "Spindeltasten abgelehnt: ein Programm ist aktiv"},
    // Start of a program the NC compiler has not made runnable (D-026)
    {"ALARM_START_COMPILER_ERRORS",
     "Start abgelehnt: Programm %1 hat Compilerfehler \u2014 siehe Fehlerfenster"},
    {"ALARM_START_USER_COMPILER_BUSY",
     "Start abgelehnt: Programm %1 wird compiliert (Anwender-Compiler) \u2014 danach erneut "
     "Start"},
    // The GAX wait for an axis another process holds (D-026)
    {"ALARM_WAIT_AXIS", "Warten auf Achse %1 (GAX: ein anderer Prozess belegt sie)"},
    // Prompts of a held program (D-026)
    {"PROMPT_PROGRAMMED_STOP", "Programmierter Halt: Start drücken zum Fortsetzen"},
    {"PROMPT_SINGLE_BLOCK", "Einzelsatz: Start drücken für den nächsten Satz"},
    // MDI: refusals, the MDI screen's messages and the history's outcomes (D-026)
    {"ALARM_MDI_NOT_MDI_MODE", "MDI abgelehnt: zuerst Betriebsart MDI anwählen"},
    {"ALARM_MDI_PROGRAM_ACTIVE",
     "MDI abgelehnt: ein Programm ist aktiv (erst Steuerung rücksetzen)"},
    {"MDI_TEXT_ABANDONED", "MDI-Eingabe abgebrochen (Steuerung rücksetzen)"},
    {"MDI_TEXT_CANNOT_RUN", "MDI: die Eingabe ist nicht ausführbar"},
    {"MDI_TEXT_DONE", "MDI-Eingabe ausgeführt"},
    {"MDI_TEXT_INPUT_CORRECT", "Eingabe korrekt: %1"},
    {"MDI_TEXT_OUTCOME_DONE", "ausgeführt"},
    {"MDI_TEXT_OUTCOME_ERROR", "Fehler Zeile %1: %2"},
    {"MDI_TEXT_OUTCOME_RESET", "abgebrochen"},
    {"MDI_TEXT_OUTCOME_RUNNING", "läuft"},
    {"MDI_TEXT_RECALLED", "Eingabe %1 zurückgeholt: Start führt sie aus"},
    {"MDI_TEXT_RUNNING", "MDI-Eingabe läuft"},
};
}  // namespace

MessageTable alarmMessages() {
    return {kAlarmMessages, sizeof kAlarmMessages / sizeof kAlarmMessages[0]};
}

}  // namespace mtc::core::messages
