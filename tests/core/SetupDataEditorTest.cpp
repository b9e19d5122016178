// Operator changes of tool lists and zero offsets (SetupDataEditor, used by
// the panel's tool and zero offset screens and by `tools|offsets set`): the
// file rules check every value, a refused change changes nothing, an
// accepted one is saved at once under the data file's lock, another
// program's save is taken over, never written back over.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "InterpTestSupport.h"
#include "cnc_core/tooldata/SetupDataEditor.h"

namespace {

using namespace mtc::core;
using namespace mtc::test;
namespace fs = std::filesystem;

/// A demo cell's data kept in a fresh folder.
struct EditedCell {
    fs::path dir;
    SetupDataFiles files;
    DiagnosticList diagnostics;
    SetupData data = SetupData::fromConfig(demoCell(), diagnostics);

    EditedCell() {
        char pattern[] = "/tmp/mtc-setup-editor-XXXXXX";
        dir = ::mkdtemp(pattern);
        files = setupDataFilesBeside((dir / "cell.mdt").string());
    }
    ~EditedCell() { fs::remove_all(dir); }

    /// The data as a fresh program reads it from the files.
    SetupData reread() const {
        DiagnosticList problems;
        SetupData other = SetupData::fromConfig(demoCell(), problems);
        EXPECT_TRUE(other.load(files, problems)) << diagnosticsText(problems);
        return other;
    }
    static std::string text(const std::string& path) {
        std::ifstream in(path);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
};

TEST(SetupDataEditor, AToolValueIsCheckedTakenAndSaved) {
    EditedCell cell;
    SetupDataEditor editor(cell.data, cell.files);
    const std::shared_ptr<ToolList> mill = cell.data.tools(0);
    SetupDataEdit edit = editor.setToolValues(0, 1, 1, {{"radius", "4.25"}, {"l3_wear", "-0.02"}});
    EXPECT_TRUE(edit.changed);
    EXPECT_TRUE(edit.saved) << diagnosticsText(edit.diagnostics);
    EXPECT_EQ(mill->edge(1, 1)->radius, 4.25) << "the list the interpreter reads";
    EXPECT_EQ(cell.reread().tools(0)->edge(1, 1)->length3Wear, -0.02);
    EXPECT_EQ(cell.reread().tools(0)->edge(1, 1)->radius, 4.25);

    const std::string before = EditedCell::text(cell.files.tools);
    edit = editor.setToolValues(0, 1, 1, {{"l1", "7"}, {"radius", "-1"}});
    EXPECT_FALSE(edit.changed);
    EXPECT_FALSE(edit.saved);
    EXPECT_EQ(edit.reason(), "key 'radius' = '-1': out of range (allowed 0 .. 999.99999 mm)");
    EXPECT_EQ(mill->edge(1, 1)->length1, 0.0) << "all or none";
    EXPECT_EQ(EditedCell::text(cell.files.tools), before);
    EXPECT_EQ(editor.setToolValues(0, 1, 1, {{"orientation", "2.5"}}).reason(),
              "key 'orientation' = '2.5': not a whole number (allowed 0 .. 9)");
    EXPECT_NE(editor.setToolValues(0, 1, 1, {{"name", "bad name"}}).reason().find("allowed 1..24"),
              std::string::npos);
    EXPECT_TRUE(editor.setToolValues(0, 1, 1, {{"name", "rough-mill"}}).saved);
    EXPECT_EQ(cell.reread().tools(0)->find(1)->name, "rough-mill");
}

TEST(SetupDataEditor, ToolsAndEdgesAreAddedAndRemoved) {
    EditedCell cell;
    SetupDataEditor editor(cell.data, cell.files);
    EXPECT_EQ(editor.addTool(0, "T1").reason(), "T1 is already in the tool list");
    EXPECT_EQ(editor.addTool(0, "0").reason(),
              "key 'T' = '0': out of range (allowed 1 .. 9999999)");
    EXPECT_EQ(editor.addTool(0, "x7").reason(),
              "key 'T' = 'x7': not a whole number (allowed 1 .. 9999999)");
    EXPECT_TRUE(editor.addTool(0, "T4711").saved);
    ASSERT_NE(cell.data.tools(0)->edge(4711, 1), nullptr);
    EXPECT_EQ(cell.data.tools(0)->edge(4711, 1)->radius, 0.0);
    EXPECT_EQ(editor.addEdge(0, 4711, "10").reason(),
              "key 'E' = '10': out of range (allowed 1 .. 9)");
    EXPECT_EQ(editor.addEdge(0, 4711, "1").reason(), "T4711 E1 is already in the tool list");
    EXPECT_EQ(editor.addEdge(0, 4712, "2").reason(), "T4712 is not in the tool list");
    EXPECT_TRUE(editor.addEdge(0, 4711, "E3").saved);
    EXPECT_EQ(cell.reread().tools(0)->find(4711)->edges.size(), 2u);
    EXPECT_TRUE(editor.removeEdge(0, 4711, 1).saved);
    EXPECT_EQ(editor.removeEdge(0, 4711, 1).reason(),
              "T4711 E1 is not in the tool list of process 0");
    EXPECT_TRUE(editor.removeEdge(0, 4711, 3).saved) << "the last edge takes the tool";
    EXPECT_EQ(cell.reread().tools(0)->find(4711), nullptr);
    EXPECT_TRUE(editor.removeTool(1, 12).saved);
    EXPECT_EQ(cell.reread().tools(1)->find(12), nullptr);
    EXPECT_NE(cell.reread().tools(1)->find(11), nullptr);
}

TEST(SetupDataEditor, ZeroOffsetsAreCheckedAndSaved) {
    EditedCell cell;
    SetupDataEditor editor(cell.data, cell.files);
    EXPECT_TRUE(editor.setOffsets(0, 54, {{"X", "-140.5"}}).saved);
    EXPECT_EQ(cell.data.offsets(0)->value(54, AxisDefinition::X), -140.5);
    EXPECT_EQ(cell.reread().offsets(0)->value(54, AxisDefinition::X), -140.5);
    EXPECT_EQ(cell.reread().offsets(0)->value(54, AxisDefinition::Y), -80.0);
    SetupDataEdit edit = editor.setOffsets(1, 54, {{"Z", "1e6"}});
    EXPECT_FALSE(edit.changed);
    EXPECT_EQ(edit.reason(),
              "key 'Z' = '1e6': out of range (allowed -99999.9999 .. 99999.9999 mm or degrees)");
    EXPECT_EQ(cell.data.offsets(1)->value(54, AxisDefinition::Z), 255.5);
    EXPECT_EQ(editor.setOffsets(1, 54, {{"Q", "1"}}).reason(),
              "key 'Q' = '1': not an axis definition (allowed X Y Z U V W A B C)");
    EXPECT_EQ(editor.setOffsets(1, 54, {{"Z", "1,5"}}).reason(),
              "key 'Z' = '1,5': not a decimal number (allowed -99999.9999 .. 99999.9999 mm or "
              "degrees)");
}

// One writer at a time, and nothing older written over something newer:
// another program's save of process 1 is taken over by this program's
// next change of process 0, and both are in the file.
TEST(SetupDataEditor, AnotherProgramsSaveIsTakenOverNotOverwritten) {
    EditedCell cell;
    SetupDataEditor panel(cell.data, cell.files);
    ASSERT_TRUE(panel.setToolValues(0, 1, 1, {{"radius", "4"}}).saved);
    {
        DiagnosticList problems;
        SetupData other = SetupData::fromConfig(demoCell(), problems);
        SetupDataEditor cli(other, cell.files, "command line");
        ASSERT_TRUE(other.load(cell.files, problems));
        ASSERT_TRUE(cli.setToolValues(1, 2, 1, {{"radius", "0.8"}}).saved);
        ASSERT_TRUE(cli.setOffsets(1, 55, {{"X", "250"}}).saved);
    }
    SetupDataEdit edit = panel.setToolValues(0, 2, 1, {{"radius", "5.5"}});
    EXPECT_TRUE(edit.saved);
    ASSERT_FALSE(edit.diagnostics.empty());
    EXPECT_EQ(edit.diagnostics.items().front().code, "SETUP_DATA_TAKEN_OVER");
    EXPECT_EQ(cell.data.tools(1)->edge(2, 1)->radius, 0.8) << "taken over into the live list";
    const SetupData file = cell.reread();
    EXPECT_EQ(file.tools(1)->edge(2, 1)->radius, 0.8);
    EXPECT_EQ(file.tools(0)->edge(2, 1)->radius, 5.5);
    EXPECT_EQ(file.tools(0)->edge(1, 1)->radius, 4.0);
    EXPECT_TRUE(panel.setOffsets(0, 54, {{"Y", "-70"}}).saved);
    EXPECT_EQ(cell.reread().offsets(1)->value(55, AxisDefinition::X), 250.0);
}

// The panel looks at the files every second: another program's save is
// taken over without a change of its own; a refused file is said once.
TEST(SetupDataEditor, RefreshTakesOverAnotherProgramsSave) {
    EditedCell cell;
    SetupDataEditor panel(cell.data, cell.files);
    DiagnosticList notes;
    EXPECT_FALSE(panel.refresh(notes));
    EXPECT_TRUE(notes.empty());
    {
        DiagnosticList problems;
        SetupData other = SetupData::fromConfig(demoCell(), problems);
        SetupDataEditor cli(other, cell.files, "command line");
        ASSERT_TRUE(cli.setToolValues(0, 3, 1, {{"radius_wear", "-0.05"}}).saved);
        ASSERT_TRUE(cli.setOffsets(0, 57, {{"Z", "12"}}).saved);
    }
    EXPECT_TRUE(panel.refresh(notes));
    EXPECT_EQ(notes.size(), 2u);
    EXPECT_EQ(cell.data.tools(0)->edge(3, 1)->radiusWear, -0.05);
    EXPECT_EQ(cell.data.offsets(0)->value(57, AxisDefinition::Z), 12.0);
    notes.clear();
    EXPECT_FALSE(panel.refresh(notes)) << "nothing new";
    EXPECT_TRUE(notes.empty());
    { std::ofstream(cell.files.tools) << "format = mtc200-tools 1\n[process 0]\nT1 E1 radius=x\n"; }
    EXPECT_FALSE(panel.refresh(notes));
    EXPECT_TRUE(notes.hasErrors());
    notes.clear();
    EXPECT_FALSE(panel.refresh(notes));
    EXPECT_TRUE(notes.empty()) << "a refused file is said once";
    EXPECT_EQ(cell.data.tools(0)->edge(1, 1)->radius, 3.5);
    EXPECT_FALSE(panel.setToolValues(0, 1, 1, {{"radius", "4"}}).saved) << "and not overwritten";
}

TEST(SetupDataEditor, ALockedFileIsNotWrittenButTheChangeHolds) {
    EditedCell cell;
    SetupDataEditor editor(cell.data, cell.files, "entry", 0.05);
    FileLock other(cell.files.tools);
    ASSERT_TRUE(other.locked());
    const SetupDataEdit edit = editor.setToolValues(0, 1, 1, {{"radius", "4"}});
    EXPECT_TRUE(edit.changed);
    EXPECT_FALSE(edit.saved);
    EXPECT_NE(edit.reason().find("NOT saved"), std::string::npos) << edit.reason();
    EXPECT_FALSE(fs::exists(cell.files.tools));
}

TEST(SetupDataEditor, ADamagedFileIsNeverOverwritten) {
    EditedCell cell;
    SetupDataEditor editor(cell.data, cell.files);
    { std::ofstream(cell.files.offsets) << "format = mtc200-offsets 1\n[process 0]\nG54 X=1\n"; }
    const SetupDataEdit edit = editor.setOffsets(0, 54, {{"X", "2"}});
    EXPECT_TRUE(edit.changed);
    EXPECT_FALSE(edit.saved);
    EXPECT_NE(edit.reason().find("cut off"), std::string::npos) << edit.reason();
    EXPECT_NE(diagnosticsText(edit.diagnostics).find("it is not overwritten"), std::string::npos);
    EXPECT_EQ(EditedCell::text(cell.files.offsets),
              "format = mtc200-offsets 1\n[process 0]\nG54 X=1\n");
}

TEST(SetupDataEditor, WithoutFilesTheChangeHoldsUnsaved) {
    DiagnosticList problems;
    SetupData data = SetupData::fromConfig(demoCell(), problems);
    SetupDataEditor editor(data, {});
    const SetupDataEdit edit = editor.setOffsets(0, 56, {{"Z", "-3"}});
    EXPECT_TRUE(edit.changed);
    EXPECT_FALSE(edit.saved);
    EXPECT_TRUE(edit.diagnostics.empty());
    EXPECT_EQ(data.offsets(0)->value(56, AxisDefinition::Z), -3.0);
}

}  // namespace
