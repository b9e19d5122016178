// The German message table of the core's diagnostics (issue 20 §1,
// docs/DECISIONS.md D-023): every code the core's sources can emit has a
// German brief message, the table holds no code the core no longer has,
// and the German text keeps the core's English message (with its values)
// as additional text.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "cnc_core/language/Parser.h"
#include "cnc_core/text/Messages.h"

using namespace mtc::core;

namespace {

namespace fs = std::filesystem;

/// Upper-case literals with an underscore in the core that are not
/// diagnostic codes: compiler and GNE keywords, NC option keys, environment
/// variables. A new literal of that shape is either a code (give it a German
/// row in cnc_core/text/*Messages.cpp) or belongs here.
bool isNotACode(const std::string& literal) {
    static const std::set<std::string> kKeywordsAndNames = {
        "ACC_EFF",         "ACD_COMP", "END_CONT",          "LA_ON",
        "LA_OFF",          "MODF_ON",  "MODF_OFF",          "TL_RADIUS",
        "COMPILER_ACTIVE", "CYCLE_MP", "SOURCE_DATE_EPOCH", "XDG_STATE_HOME"};
    static const std::regex kGneCalls("(CYCLE|FORM|WINDOW)_[0-9]+");
    return kKeywordsAndNames.count(literal) > 0 || std::regex_match(literal, kGneCalls);
}

/// The code-shaped string literals of one source text ("PARSE_BAD_LABEL").
std::set<std::string> codeLiterals(const std::string& source) {
    static const std::regex kLiteral("\"([A-Z][A-Z0-9]*(?:_[A-Z0-9]+)+)\"");
    std::set<std::string> found;
    for (auto it = std::sregex_iterator(source.begin(), source.end(), kLiteral);
         it != std::sregex_iterator(); ++it)
        if (!isNotACode((*it)[1].str())) found.insert((*it)[1].str());
    return found;
}

/// The table's own files: their literals are the table, not emissions.
bool isMessageTable(const fs::path& path) {
    return path.parent_path().filename() == "text" &&
           path.filename().string().find("Messages") != std::string::npos;
}

std::set<std::string> codesInCoreSources() {
    std::set<std::string> codes;
    for (const auto& entry :
         fs::recursive_directory_iterator(fs::path(MTC_SOURCE_DIR) / "cnc_core")) {
        const fs::path& path = entry.path();
        if (!entry.is_regular_file() || isMessageTable(path)) continue;
        if (path.extension() != ".cpp" && path.extension() != ".h") continue;
        std::ifstream in(path);
        std::stringstream text;
        text << in.rdbuf();
        for (const std::string& code : codeLiterals(text.str()))
            codes.insert(code);
    }
    return codes;
}

/// The codes of `codes` the table has no German text for, space-separated.
std::string withoutGerman(const std::set<std::string>& codes) {
    std::string missing;
    for (const std::string& code : codes)
        if (germanMessage(code).empty()) missing += code + " ";
    return missing;
}

/// An error diagnostic with `code`, `message` and `details`, no place.
Diagnostic errorWith(std::string code, std::string message, std::vector<std::string> details) {
    Diagnostic d;
    d.code = std::move(code);
    d.message = std::move(message);
    d.details = std::move(details);
    return d;
}

}  // namespace

TEST(MessageTable, EveryCodeInTheCoreSourcesHasAGermanText) {
    const std::set<std::string> codes = codesInCoreSources();
    ASSERT_GT(codes.size(), 300u) << "the scan of " MTC_SOURCE_DIR "/cnc_core found too little";
    EXPECT_EQ(withoutGerman(codes), "") << "add a German row to cnc_core/text/*Messages.cpp";
}

TEST(MessageTable, TheCheckCatchesANewCodeWithoutGermanText) {
    const std::string probe =
        "diagnostics.error(\"PROBE_NEW_CODE\", {}, \"a message nobody translated\");\n"
        "report(i, \"LA_NESTED\", \"LA_ON inside an LA segment\");\n";
    const std::set<std::string> codes = codeLiterals(probe);
    EXPECT_EQ(codes, (std::set<std::string>{"LA_NESTED", "PROBE_NEW_CODE"}));
    EXPECT_EQ(withoutGerman(codes), "PROBE_NEW_CODE ");
}

TEST(MessageTable, HoldsEachCodeOnceAndOnlyCodesTheCoreHas) {
    const std::set<std::string> inSources = codesInCoreSources();
    std::set<std::string> seen;
    for (std::string_view code : messageCodes()) {
        EXPECT_TRUE(seen.insert(std::string(code)).second) << "twice in the table: " << code;
        EXPECT_TRUE(inSources.count(std::string(code))) << "no longer in the core: " << code;
        EXPECT_FALSE(germanMessage(code).empty()) << code;
    }
}

TEST(MessageTable, GermanBriefMessageKeepsTheEnglishMessageWithItsValues) {
    const Program program = parseProgram("N0001 G1 X10 F100 WOBBLE\nN0002 PROGRAMMENDE\n");
    ASSERT_FALSE(program.diagnostics.empty());
    const Diagnostic& d = program.diagnostics.items().front();
    ASSERT_EQ(d.code, "PARSE_UNKNOWN_WORD");
    ASSERT_NE(d.message.find("WOBBLE"), std::string::npos) << d.message;

    const DiagnosticText german = diagnosticText(d, Language::German);
    EXPECT_EQ(german.brief, "Unbekanntes Wort");
    ASSERT_FALSE(german.additional.empty());
    EXPECT_EQ(german.additional.front(), d.message);

    const DiagnosticText english = diagnosticText(d, Language::English);
    EXPECT_EQ(english.brief, d.message);
    EXPECT_EQ(english.additional, d.details);
}

TEST(MessageTable, ACodeWithoutARowKeepsItsEnglishText) {
    const Diagnostic d = errorWith("MY_COMPILER_7", "user text", {"line 2"});
    const DiagnosticText text = diagnosticText(d, Language::German);
    EXPECT_EQ(text.brief, "user text");
    EXPECT_EQ(text.additional, std::vector<std::string>{"line 2"});
}

TEST(MessageTable, DetailsEqualToTheMessageAreNotRepeated) {
    const Diagnostic d = errorWith("USER_COMPILER_FAILED", "User compiler 1: failed",
                                   {"User compiler 1: failed", "exit status 2"});
    const DiagnosticText text = diagnosticText(d, Language::German);
    EXPECT_EQ(text.brief, "Anwender-Compiler fehlgeschlagen");
    EXPECT_EQ(text.additional,
              (std::vector<std::string>{"User compiler 1: failed", "exit status 2"}));
}

// One-line texts (alarm line, message lines, D-024): German brief message
// first, the English message with its values after it; English unchanged.
TEST(MessageTable, OneLineTextsInGermanKeepTheValues) {
    Diagnostic d =
        errorWith("AXIS_UNKNOWN", "this process has no axis A", {"MDI input line 2: G1 A1"});
    d.where.program = 5;
    d.where.block = "N0010";
    d.where.line = 3;
    EXPECT_EQ(messageLine(d, Language::English), "this process has no axis A");
    EXPECT_EQ(messageLine(d, Language::German),
              "Achse oder Spindel im Prozess nicht vorhanden — this process has no axis A");
    EXPECT_EQ(formatDiagnostic(d, Language::English), formatDiagnostic(d));
    EXPECT_EQ(formatDiagnostic(d, Language::German),
              "Fehler [AXIS_UNKNOWN] Programm 5 N0010 Zeile 3: Achse oder Spindel im Prozess "
              "nicht vorhanden — this process has no axis A\n    MDI input line 2: G1 A1");
    const Diagnostic own = errorWith("MY_COMPILER_7", "user text", {});
    EXPECT_EQ(messageLine(own, Language::German), "user text");
    EXPECT_EQ(severityWord(own, Language::German), "Fehler");
}

// Alarms without a diagnostic (D-025): German from the table, English as
// written, a code without a row as written.
TEST(MessageTable, AlarmsOfTheControlKeys) {
    const std::string english = "Start refused: no program selected";
    EXPECT_EQ(alarmText("ALARM_START_NO_PROGRAM", english, Language::German),
              "Start abgelehnt: kein Programm angewählt");
    EXPECT_EQ(alarmText("ALARM_START_NO_PROGRAM", english, Language::English), english);
    EXPECT_EQ(alarmText("ALARM_NOBODY_WROTE", english, Language::German), english);
}

// Alarms with values (D-026): both languages fill "%1"… from the same
// values; a value is never filled again, a "%" without a value stays.
TEST(MessageTable, AlarmsWithValues) {
    const std::string english = "%1 is at its travel limit";
    EXPECT_EQ(alarmText("ALARM_JOG_AT_LIMIT", english, Language::German, {"Z"}),
              "Z steht an der Verfahrgrenze");
    EXPECT_EQ(alarmText("ALARM_JOG_AT_LIMIT", english, Language::English, {"Z"}),
              "Z is at its travel limit");
    EXPECT_EQ(fillIn("%2 of %1, 100%", {"a%2", "b"}), "b of a%2, 100%");
    EXPECT_EQ(fillIn("%3 %0 %", {"a"}), "%3 %0 %");
}

TEST(MessageTable, LanguageTags) {
    EXPECT_EQ(languageFromTag("de"), Language::German);
    EXPECT_EQ(languageFromTag("de_DE.UTF-8"), Language::German);
    EXPECT_EQ(languageFromTag("de-AT"), Language::German);
    EXPECT_EQ(languageFromTag("en"), Language::English);
    EXPECT_EQ(languageFromTag("en_GB"), Language::English);
    EXPECT_EQ(languageFromTag("C"), Language::English);
    EXPECT_EQ(languageFromTag("fr_FR"), std::nullopt);
    EXPECT_EQ(languageFromTag(""), std::nullopt);
}
