// The machine configuration validated as a whole (issue 22 §2): every key of
// the rule table (ConfigSchema.h) mutated with the values that were accepted
// before (nan, inf, empty, text, huge, negative, hex, decimal comma,
// denormal, duplicate) must be refused with file, line, key, value and the
// allowed range; the boundaries of every range must be accepted; every cut
// of a file must be refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include "cnc_core/machine/ConfigSchema.h"
#include "cnc_core/machine/ConfigText.h"
#include "cnc_core/machine/MachineConfigReader.h"
#include "resources/EmbeddedResources.h"

namespace {

using namespace mtc::core;

/// One line of the test cell: its section kind, key and value.
struct CellLine {
    std::string header;  ///< a section header line ("" for key lines)
    ConfigSection section = ConfigSection::Cell;
    std::string key;
    std::string value;
};

CellLine header(const std::string& text) {
    return {text, ConfigSection::Cell, "", ""};
}

/// A cell with every key of every section, each once.
std::vector<CellLine> fullCell() {
    using S = ConfigSection;
    return {
        header("[cell]"),
        {"", S::Cell, "name", "full cell"},
        {"", S::Cell, "md_password", "secret"},
        header("[process 0]"),
        {"", S::Process, "name", "mill"},
        {"", S::Process, "tool_places", "24"},
        {"", S::Process, "tool_storage", "magazine"},
        {"", S::Process, "stock", "block -10 10 -10 10 -10 0"},
        {"", S::Process, "B004", "17"},
        {"", S::Process, "B015", "radius"},
        {"", S::Process, "B033", "no"},
        {"", S::Process, "B036", "no"},
        {"", S::Process, "B058", "no"},
        {"", S::Process, "B059", "no"},
        {"", S::Process, "B060", "no"},
        {"", S::Process, "B061", "no"},
        {"", S::Process, "B062", "yes"},
        {"", S::Process, "B063", "10"},
        {"", S::Process, "B064", "50"},
        {"", S::Process, "B065", "10"},
        {"", S::Process, "B066", "30"},
        {"", S::Process, "B067", "70"},
        {"", S::Process, "B068", "1"},
        {"", S::Process, "B069", "200"},
        {"", S::Process, "B070", "5"},
        {"", S::Process, "B071", "1"},
        {"", S::Process, "B072", "3"},
        {"", S::Process, "B073", "2"},
        {"", S::Process, "B074", "150"},
        header("[process 0 axis X]"),
        {"", S::Axis, "kind", "linear"},
        {"", S::Axis, "definition", "X"},
        {"", S::Axis, "designation2", "X1"},
        {"", S::Axis, "polar_direction", "0"},
        {"", S::Axis, "min", "-400"},
        {"", S::Axis, "max", "400"},
        {"", S::Axis, "max_velocity", "30000"},
        {"", S::Axis, "max_acceleration", "2500"},
        header("[process 0 axis Y]"),
        {"", S::Axis, "definition", "Y"},
        header("[process 0 axis Z]"),
        {"", S::Axis, "definition", "Z"},
        header("[process 0 spindle S1]"),
        {"", S::Spindle, "index", "1"},
        {"", S::Spindle, "rotary_axis", "C"},
        {"", S::Spindle, "definition", "C"},
        {"", S::Spindle, "designation2", "Y1"},
        {"", S::Spindle, "polar_direction", "1"},
        {"", S::Spindle, "max_speed", "8000"},
        {"", S::Spindle, "max_velocity", "36000"},
        {"", S::Spindle, "max_acceleration", "7200"},
        header("[process 0 mgroup 2]"),
        {"", S::MGroup, "name", "spindle"},
        {"", S::MGroup, "functions", "3 4 5"},
        {"", S::MGroup, "reset", "5"},
        header("[process 0 tools]"),
        {"", S::Tools, "T1", "radius 3 length 80 edge 2 name mill1"},
        header("[process 0 zero-offsets]"),
        {"", S::ZeroOffsets, "G54", "X-150 Y-80 Z-120"},
        header("[process 0 torque-model]"),
        {"", S::TorqueModel, "stall", "0"},
        {"", S::TorqueModel, "friction_rest", "6"},
        {"", S::TorqueModel, "friction_max", "10"},
        {"", S::TorqueModel, "cutting", "60"},
        {"", S::TorqueModel, "reference_feed", "1000"},
        {"", S::TorqueModel, "exponent", "0.8"},
        {"", S::TorqueModel, "load", "0"},
        {"", S::TorqueModel, "noise", "1"},
        {"", S::TorqueModel, "seed", "2002"},
        {"", S::TorqueModel, "engagement", "1"},
        header("[process 0 page 180]"),
        {"", S::Page, "title", "transfer"},
        {"", S::Page, "element 1", "direction | SINT | 0 | 2 | 0 | - | nc"},
        header("[end]"),
    };
}

std::string textOf(const std::vector<CellLine>& lines) {
    std::string text;
    for (const CellLine& l : lines)
        text += l.header.empty() ? l.key + " = " + l.value + "\n" : l.header + "\n";
    return text;
}

MachineConfigReadResult read(const std::string& text) {
    MachineConfigReadOptions options;
    options.fileName = "full.cfg";
    options.requireEndMarker = true;
    return readMachineConfig(text, options);
}

std::string allDiagnostics(const MachineConfigReadResult& r) {
    std::string text;
    for (const Diagnostic& d : r.diagnostics.items())
        text += formatDiagnostic(d) + "\n";
    return text;
}

/// Index of the line of `key` in `section` (the lines are 0-based, the file's 1-based).
std::size_t lineOf(const std::vector<CellLine>& cell, ConfigSection section, const std::string& key) {
    for (std::size_t i = 0; i < cell.size(); ++i)
        if (cell[i].header.empty() && cell[i].section == section && cell[i].key == key) return i;
    ADD_FAILURE() << "the test cell has no key " << key;
    return 0;
}

/// Replaces the value of line `index`, reads, and checks that exactly that
/// line is refused with a message naming file, key, value and range.
void expectRefused(std::vector<CellLine> cell, std::size_t index, const std::string& value,
                   const std::string& why, bool nameRange = true) {
    const std::string key = cell[index].key;
    cell[index].value = value;
    const MachineConfigReadResult r = read(textOf(cell));
    SCOPED_TRACE(key + " = '" + value + "' (" + why + ")\n" + allDiagnostics(r));
    ASSERT_FALSE(r.ok());
    const Diagnostic& d = r.diagnostics.items().front();
    EXPECT_EQ(d.where.line, static_cast<int>(index) + 1);
    EXPECT_EQ(d.message.rfind("full.cfg: ", 0), 0u) << "the file is named first";
    EXPECT_NE(d.message.find(key), std::string::npos) << "the key is named";
    EXPECT_NE(d.message.find(quotedValue(value)), std::string::npos) << "the value is named";
    if (nameRange) {
        EXPECT_NE(d.message.find("allowed: "), std::string::npos) << "the range";
    }
}

void expectAccepted(std::vector<CellLine> cell, std::size_t index, const std::string& value) {
    cell[index].value = value;
    const MachineConfigReadResult r = read(textOf(cell));
    EXPECT_TRUE(r.ok()) << cell[index].key << " = " << value << "\n" << allDiagnostics(r);
}

std::string number(double value) {
    std::ostringstream out;
    out.precision(17);
    out << value;
    return out.str();
}

TEST(MachineConfigValidation, TheFullTestCellIsValid) {
    const MachineConfigReadResult r = read(textOf(fullCell()));
    EXPECT_TRUE(r.ok()) << allDiagnostics(r);
    EXPECT_TRUE(r.diagnostics.empty()) << allDiagnostics(r);
}

/// Every key of the table that is a plain `key = value` line.
TEST(MachineConfigValidation, EveryKeyRefusesEveryMutation) {
    const std::vector<CellLine> cell = fullCell();
    std::size_t checked = 0;
    for (const ConfigRule& rule : configRules()) {
        if (rule.type == ConfigValueType::Form || rule.key.front() == '(') continue;
        if (rule.section == ConfigSection::Tools || rule.section == ConfigSection::ZeroOffsets ||
            (rule.section == ConfigSection::Page && rule.key != "title"))
            continue;  // parts of a line: FieldsOfToolsOffsetsAndPagesAreChecked
        const std::size_t at = lineOf(cell, rule.section, std::string(rule.key));
        ++checked;
        expectRefused(cell, at, "", "empty");
        if (rule.type != ConfigValueType::Text && rule.type != ConfigValueType::Word) {
            for (const char* bad : {"abc", "nan", "5,5", "0x10", "inf"})
                expectRefused(cell, at, bad, "not a value of this key");
        }
        if (rule.type == ConfigValueType::Number || rule.type == ConfigValueType::Whole) {
            for (const char* bad :
                 {"-inf", "1e308", "-1e308", "1e-320", "NaN", "1e999", "+", "1 2"}) {
                expectRefused(cell, at, bad, "not a finite number in range");
            }
            expectRefused(cell, at, number(rule.minimum - std::max(1.0, rule.minimum * 0.5)),
                          "below the minimum");
            expectRefused(cell, at, number(rule.maximum + std::max(1.0, rule.maximum)),
                          "above the maximum");
            if (rule.minimum >= 0) {
                expectRefused(cell, at, "-1", "negative");
            }
            if (rule.type == ConfigValueType::Whole) {
                expectRefused(cell, at, "1.5", "not whole");
            }
            // The boundaries are accepted (except where another key forbids it:
            // min < max of an axis, the reset value one of the group's functions).
            const bool other = rule.key == "min" || rule.key == "max" || rule.key == "reset";
            if (!other || rule.key == "min" || rule.key == "reset") {
                expectAccepted(cell, at, number(rule.minimum));
            }
            if (!other || rule.key == "max") {
                expectAccepted(cell, at, number(rule.maximum));
            }
        }
        if (rule.type == ConfigValueType::Choice) {
            std::istringstream words{std::string(rule.choices)};
            for (std::string word; words >> word;) {
                expectAccepted(cell, at, word);
            }
        }
        if (rule.type == ConfigValueType::Text || rule.type == ConfigValueType::Word) {
            expectRefused(cell, at, std::string(static_cast<std::size_t>(rule.maximum) + 1, 'x'),
                          "too long");
            expectRefused(cell, at, "a\x01z", "control character");
            expectRefused(cell, at, "bad\xff\xfe", "not UTF-8");
            expectAccepted(cell, at, std::string(static_cast<std::size_t>(rule.maximum), 'x'));
            if (rule.type == ConfigValueType::Word) {
                expectRefused(cell, at, "two words", "blank");
            }
        }
        // The same key twice: the second line is refused, naming the first.
        std::vector<CellLine> twice = cell;
        twice.insert(twice.begin() + static_cast<long>(at) + 1, cell[at]);
        const MachineConfigReadResult r = read(textOf(twice));
        ASSERT_FALSE(r.ok()) << rule.key << " twice";
        EXPECT_EQ(r.diagnostics.items().front().code, "CFG_DUPLICATE");
        EXPECT_EQ(r.diagnostics.items().front().where.line, static_cast<int>(at) + 2);
    }
    EXPECT_GT(checked, 40u);
}

TEST(MachineConfigValidation, FieldsOfToolsOffsetsAndPagesAreChecked) {
    const std::vector<CellLine> cell = fullCell();
    const std::size_t tool = lineOf(cell, ConfigSection::Tools, "T1");
    for (const char* bad :
         {"", "radius nan length 80", "radius 3", "length 80", "radius inf length 80",
          "radius -1 length 80", "radius 3 length 1e308", "radius 3 length 80 edge 10",
          "radius 3 length 80 edge 1.5", "radius 3 length 80 radius 4", "radius 0x10 length 80",
          "radius 5,5 length 80", "radius 3 length 80 colour red", "radius 3 length",
          "radius 1e-320 length 80"})
        expectRefused(cell, tool, bad, "tool data");
    expectAccepted(cell, tool, "radius 0 length 0 edge 9 name x");
    expectAccepted(cell, tool, "length 10000 radius 1000");

    const std::size_t offset = lineOf(cell, ConfigSection::ZeroOffsets, "G54");
    for (const char* bad : {"", "X1e308", "Xnan", "Xinf", "X", "Q5", "X1 X2", "X0x10", "X5,5",
                            "X-1e-320", "X1 Y", "1X"})
        expectRefused(cell, offset, bad, "zero offset");
    expectAccepted(cell, offset, "X-1000000 Y1000000 C0");

    const std::size_t element = lineOf(cell, ConfigSection::Page, "element 1");
    for (const char* bad :
         {"", "d | SINT | 0 | 2", "d | SINT | nan | 2 | 0", "d | SINT | 0 | inf | 0",
          "d | SINT | 0 | 2 | 3", "d | SINT | 0 | 200 | 0", "d | SINT | 0 | 2 | 0.5",
          "d | WORD | 0 | 2 | 0", "| SINT | 0 | 2 | 0", "d | SINT | 0 || 2 | 0",
          "d | BOOL | 0 | 2 | 0", "d | REAL | 0 | 1e308 | 0", "d | SINT | 2 | 0 | 1",
          "d | SINT | 0 | 2 | 0 | mm | everyone", "d | SINT | 0 | 2 | 0 | two words"})
        expectRefused(cell, element, bad, "page element", false);
    expectAccepted(cell, element, "d | REAL | -1e15 | 1e15 | 0 | mm | nc sps gui password");
    expectAccepted(cell, element, "d | INT | -2147483648 | 2147483647 | 0 |");
}

TEST(MachineConfigValidation, FormsOfTheOtherSectionsAreChecked) {
    const std::vector<CellLine> cell = fullCell();
    const std::size_t stock = lineOf(cell, ConfigSection::Process, "stock");
    for (const char* bad : {"", "block nan 1 0 1 0 1", "block 0 inf 0 1 0 1", "block 0 1 0 1 0",
                            "block 0 1e308 0 1 0 1", "cylinder Q 5 0 1", "cylinder Z 0 0 1",
                            "sphere 5", "block 1 0 0 1 0 1"})
        expectRefused(cell, stock, bad, "stock");
    expectAccepted(cell, stock, "cylinder Z 40 140 257.5");
    expectAccepted(cell, stock, "none");

    const std::size_t definition = lineOf(cell, ConfigSection::Axis, "definition");
    for (const char* bad : {"", "X,,Z", "X, Y, Z, U, V", "X Z"})
        expectRefused(cell, definition, bad, "definition");

    for (ConfigSection section : {ConfigSection::Axis, ConfigSection::Spindle}) {
        const std::size_t designation = lineOf(cell, section, "designation2");
        for (const char* bad : {"", "Q", "X4", "X 1", "X1x", "nan"})
            expectRefused(cell, designation, bad, "designation 2");
        expectAccepted(cell, designation, "W3");
    }
    const std::size_t rotary = lineOf(cell, ConfigSection::Spindle, "rotary_axis");
    for (const char* bad : {"", "S", "C9", "inf"})
        expectRefused(cell, rotary, bad, "rotary axis name");

    const std::size_t functions = lineOf(cell, ConfigSection::MGroup, "functions");
    for (const char* bad : {"", "3 4 nan", "3 4 1000", "3 3 5", "3 -4 5", "3 4.5 5", "0x3 4 5"})
        expectRefused(cell, functions, bad, "M functions");
    expectAccepted(cell, functions, "0 5 999");
}

TEST(MachineConfigValidation, EveryRuleOfTheTableIsExercisedHere) {
    // A rule added to the table without a case in this file fails here.
    const std::set<std::string> forms = {"stock", "definition", "designation2", "rotary_axis",
                                         "functions", "T<n>", "radius",
                                         "length", "edge", "name", "code", "axis", "value",
                                         "element", "designation", "type", "limit", "unit",
                                         "protection", "(number)"};
    const std::vector<CellLine> cell = fullCell();
    for (const ConfigRule& rule : configRules()) {
        const bool direct = std::any_of(cell.begin(), cell.end(), [&](const CellLine& l) {
            return l.header.empty() && l.section == rule.section && l.key == rule.key;
        });
        EXPECT_TRUE(direct || forms.count(std::string(rule.key)))
            << configSectionName(rule.section) << " " << rule.key << " has no test case";
    }
}

TEST(MachineConfigValidation, CrossKeyRules) {
    const std::vector<CellLine> cell = fullCell();
    std::vector<CellLine> limits = cell;
    limits[lineOf(cell, ConfigSection::Axis, "min")].value = "500";
    EXPECT_FALSE(read(textOf(limits)).ok()) << "min above max";
    limits[lineOf(cell, ConfigSection::Axis, "min")].value = "400";
    EXPECT_FALSE(read(textOf(limits)).ok()) << "min = max switches the limit off";
    limits[lineOf(cell, ConfigSection::Axis, "min")].value = "0";
    limits[lineOf(cell, ConfigSection::Axis, "max")].value = "0";
    EXPECT_TRUE(read(textOf(limits)).ok()) << "both 0: not monitored, as documented";

    std::vector<CellLine> reset = cell;
    reset[lineOf(cell, ConfigSection::MGroup, "reset")].value = "7";
    EXPECT_FALSE(read(textOf(reset)).ok()) << "reset value outside the group";

    std::vector<CellLine> twoGroups = cell;
    twoGroups.insert(twoGroups.begin() + static_cast<long>(lineOf(cell, ConfigSection::Tools, "T1")) - 1,
                     {header("[process 0 mgroup 3]"), {"", ConfigSection::MGroup, "functions", "5 6"}});
    const MachineConfigReadResult both = read(textOf(twoGroups));
    ASSERT_FALSE(both.ok());
    EXPECT_NE(both.diagnostics.items().front().message.find("M5 is in group 3 and in group 2"),
              std::string::npos)
        << allDiagnostics(both);
}

TEST(MachineConfigValidation, UnknownKeysSectionsAndParametersAreErrors) {
    const std::string base = textOf(fullCell());
    const std::string tail = "[end]\n";
    const std::string body = base.substr(0, base.size() - tail.size());
    for (const auto& [extra, code] : std::vector<std::pair<std::string, std::string>>{
             {"[process 0]\nname = x\n", "CFG_DUPLICATE"},
             {"[process 0 axis X]\n", "CFG_DUPLICATE"},
             {"[process 0 spindle X]\n", "CFG_AXIS"},
             {"[process 0 tools]\n", "CFG_DUPLICATE"},
             {"[process 0 page 180]\n", "CFG_DUPLICATE"},
             {"[process 0 mgroup 2]\n", "CFG_DUPLICATE"},
             {"[process 0 mgroup 16]\n", "CFG_MGROUP"},
             {"[process 7]\n", "CFG_PROCESS"},
             {"[process 1 axis X]\n", "CFG_PROCESS"},
             {"[process 0 gearbox]\n", "CFG_SECTION"},
             {"[cell\n", "CFG_SYNTAX"},
             {"[process 0 torque-model]\n", "CFG_DUPLICATE"}}) {
        const MachineConfigReadResult r = read(body + extra + tail);
        ASSERT_FALSE(r.ok()) << extra;
        EXPECT_EQ(r.diagnostics.items().front().code, code) << extra << allDiagnostics(r);
    }
    std::vector<CellLine> cell = fullCell();
    const std::size_t at = lineOf(cell, ConfigSection::Process, "B073");
    for (const char* key : {"B999", "B016", "B0630", "b064", "max_speed"}) {
        std::vector<CellLine> unknown = cell;
        unknown.insert(unknown.begin() + static_cast<long>(at) + 1,
                       {"", ConfigSection::Process, key, "1"});
        const MachineConfigReadResult r = read(textOf(unknown));
        ASSERT_FALSE(r.ok()) << key;
        EXPECT_EQ(r.diagnostics.items().front().code, "CFG_KEY") << key;
        EXPECT_EQ(r.diagnostics.items().front().where.line, static_cast<int>(at) + 2);
    }
}

TEST(MachineConfigValidation, EveryCutOfAFileIsRefused) {
    const std::string text = textOf(fullCell());
    const std::size_t complete = text.rfind("[end]") + 5;
    for (std::size_t cut = 0; cut < text.size(); ++cut) {
        const MachineConfigReadResult r = read(text.substr(0, cut));
        EXPECT_EQ(r.ok(), cut >= complete) << "cut after " << cut << " bytes";
    }
    const std::string demo(mtc::resources::find(mtc::resources::kDemoCellName));
    for (std::size_t cut = 0; cut + 1 < demo.size(); cut += 7)
        EXPECT_FALSE(read(demo.substr(0, cut)).ok()) << "demo cell cut after " << cut;
    EXPECT_TRUE(read(demo).ok()) << "the built-in cell carries the end marker";
}

TEST(MachineConfigValidation, TextAfterTheEndMarkerAndBinaryLinesAreRefused) {
    const std::string text = textOf(fullCell());
    EXPECT_FALSE(read(text + "name = late\n").ok());
    EXPECT_TRUE(read(text + "# a comment\n\n").ok());
    std::string binary = text;
    binary.insert(text.find("[process 0 tools]"), std::string("\x1b[2J\x00\x07\xff\n", 8));
    const MachineConfigReadResult r = read(binary);
    ASSERT_FALSE(r.ok());
    for (const Diagnostic& d : r.diagnostics.items())
        for (char c : d.message)
            EXPECT_TRUE(static_cast<unsigned char>(c) >= 0x20 && c != 0x7f)
                << "raw control byte in: " << quotedValue(d.message);
}

TEST(MachineConfigValidation, GarbageGivesBoundedMessages) {
    std::string garbage;
    for (int i = 0; i < 20000; ++i)
        garbage += "line" + std::to_string(i) + "\n";
    const MachineConfigReadResult r = read(garbage);
    EXPECT_LE(r.diagnostics.size(), 102u);
    EXPECT_EQ(r.diagnostics.items()[100].code, "CFG_TOO_MANY_ERRORS");
}

TEST(MachineConfigValidation, DocumentationTableIsTheRuleTable) {
    std::ifstream in(std::string(MTC_SOURCE_DIR) + "/docs/MACHINE-CONFIG.md");
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string doc = buffer.str();
    const std::string begin = "<!-- value-ranges:begin -->\n", end = "<!-- value-ranges:end -->";
    const std::size_t from = doc.find(begin), to = doc.find(end);
    ASSERT_NE(from, std::string::npos);
    ASSERT_NE(to, std::string::npos);
    EXPECT_EQ(doc.substr(from + begin.size(), to - from - begin.size()), configRulesMarkdown())
        << "docs/MACHINE-CONFIG.md 'Value ranges' differs from ConfigSchema.cpp; the table "
           "should read:\n"
        << configRulesMarkdown();
}

TEST(ConfigText, NumbersAreReadStrictly) {
    double v = 0;
    EXPECT_EQ(readDecimal("30000", v), NumberProblem::None);
    EXPECT_EQ(v, 30000);
    EXPECT_EQ(readDecimal("-.5", v), NumberProblem::None);
    EXPECT_EQ(v, -0.5);
    EXPECT_EQ(readDecimal("+1.5e3", v), NumberProblem::None);
    EXPECT_EQ(v, 1500);
    EXPECT_EQ(readDecimal("0x10", v), NumberProblem::NotANumber);
    EXPECT_EQ(readDecimal("5,5", v), NumberProblem::NotANumber);
    EXPECT_EQ(readDecimal("nan", v), NumberProblem::NotANumber);
    EXPECT_EQ(readDecimal("1e309", v), NumberProblem::NotFinite);
    EXPECT_EQ(readDecimal("1e-320", v), NumberProblem::Denormal);
    EXPECT_EQ(readDecimal("1e-400", v), NumberProblem::Denormal);
    EXPECT_EQ(readDecimal("", v), NumberProblem::Empty);
    EXPECT_EQ(readDecimal("1e", v), NumberProblem::NotANumber);
    EXPECT_EQ(readWholeNumber("2.5", v), NumberProblem::NotWhole);
    EXPECT_EQ(readWholeNumber("1e3", v), NumberProblem::None);
    EXPECT_EQ(readWholeNumber("1e20", v), NumberProblem::NotWhole) << "beyond 2^53";
    EXPECT_EQ(quotedValue(std::string("a\x00\x1b'\xff", 5)), "'a\\x00\\x1b\\'\\xff'");
    EXPECT_EQ(quotedValue("\xc3\xa4"), "'\xc3\xa4'") << "UTF-8 is kept";
}

}  // namespace
