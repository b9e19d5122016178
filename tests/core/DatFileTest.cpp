// .DAT program files: layout, limits, names, read/write, atomic write, loader.
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "ParserTestSupport.h"
#include "cnc_core/program/AtomicWrite.h"
#include "cnc_core/program/DatFile.h"
#include "cnc_core/program/DatFileName.h"
#include "cnc_core/program/FileText.h"
#include "cnc_core/program/ProgramLoader.h"
#include "resources/EmbeddedResources.h"
#include "tests/support/TempDir.h"

using namespace mtc::core;
using namespace mtc::core::testing;
namespace fs = std::filesystem;
using mtc::test::readWholeFile;
using mtc::test::TempDir;
using mtc::test::writeWholeFile;

namespace {

const char* kShaft =
    "iMTc/000001/01.00/0000000321/02.03.2024/10:11:12/N1010007.DAT/1\n"
    "%NPG:1:01:0:007\n"
    "!01.00\n"
    "#01Flange with bore\n"
    "$\n"
    "*Flange with bore\n"
    "%NPG\n"
    "N0000 G0 X0 Y0 Z5\n"
    "N0001 G2 X40 Y0 I20 J0 F900\n"
    "N0002 M30\n"
    "N0003 PROGRAMMENDE\n";

TEST(DatFileLayout, IdentificationHeaderAndBlocks) {
    Program p = parse(kShaft);
    ASSERT_TRUE(p.diagnostics.empty()) << formatDiagnostic(p.diagnostics.items()[0]);
    EXPECT_TRUE(p.hasDatHeader);
    EXPECT_FALSE(p.isCycle);
    EXPECT_EQ(p.identification.substr(0, 5), "iMTc/");
    EXPECT_EQ(p.header.substr(0, 15), "%NPG:1:01:0:007");
    EXPECT_EQ(p.header.substr(p.header.size() - 4), "%NPG");
    EXPECT_EQ(p.title, "Flange with bore");
    EXPECT_EQ(p.name, "Flange with bore");
    EXPECT_EQ(p.number, 7);  // from the header when not given
    ASSERT_EQ(p.blocks.size(), 4u);
    EXPECT_EQ(p.blocks[0].line, 8u);
    EXPECT_EQ(describeBlock(p, 1), "G2 X40 Y0 I20 J0 F900");
    EXPECT_TRUE(p.blocks[3].flags & kBlockProgramEnd);
}

TEST(DatFileLayout, CycleWithParameterDeclarations) {
    Program p = parse(
        "iMTc/x\n%MAC:0:03:0:019\n!01.00\n*Part transfer\n%MAC\n"
        "%CHBEGIN%\n"
        "%V% @141 INT[1,2] direction (1) or (2)\n"
        "%V% @142 REAL[-450,-0.1] transfer position\n"
        "%N% BSR .*XFER ;cycle call\n"
        "%CHEND%\n"
        ";*** comment ***\n"
        "N0000 .*XFER\nN0001 RTS\nN0002 PROGRAMMENDE\n");
    ASSERT_TRUE(p.diagnostics.empty()) << formatDiagnostic(p.diagnostics.items()[0]);
    EXPECT_TRUE(p.isCycle);
    ASSERT_EQ(p.cycleParameters.size(), 2u);
    EXPECT_EQ(p.cycleParameters[0].variable, 141);
    EXPECT_EQ(p.cycleParameters[0].type, "INT");
    EXPECT_TRUE(p.cycleParameters[0].hasRange);
    EXPECT_EQ(p.cycleParameters[0].maximum, 2.0);
    EXPECT_EQ(p.cycleParameters[0].text, "direction (1) or (2)");
    EXPECT_EQ(p.cycleParameters[1].minimum, -450.0);
    EXPECT_EQ(p.cycleParameters[1].maximum, -0.1);
    EXPECT_EQ(p.cycleCall, "BSR .*XFER ;cycle call");
    EXPECT_EQ(p.findLabel("*XFER"), 0);
}

TEST(DatFileLayout, HeaderProblems) {
    Program noId = parse("%NPG:0:01:0:001\n%NPG\nN0000 G1\nN0001 PROGRAMMENDE\n");
    EXPECT_EQ(codes(noId), std::vector<std::string>{"DAT_MISSING_IDENTIFICATION"});
    EXPECT_EQ(noId.blocks.size(), 2u);

    Program open = parse("id\n%NPG:0:01:0:001\n*title\nN0000 G1\nN0001 PROGRAMMENDE\n");
    EXPECT_EQ(codes(open), std::vector<std::string>{"DAT_UNTERMINATED_HEADER"});
    EXPECT_EQ(open.blocks.size(), 2u);  // the blocks are still read

    // Only a header, never closed: the missing PROGRAMMENDE is reported at
    // the file's last line (it said line 0 before: fuzz finding mdi 633c4f6).
    Program onlyHeader = parse("id\n%NPG:0:01:0:001\n*title\n");
    const Diagnostic* atEnd = find(onlyHeader, "DAT_MISSING_PROGRAMMENDE");
    ASSERT_NE(atEnd, nullptr);
    EXPECT_EQ(atEnd->where.line, 3);

    Program noEnd = parse("id\n%NPG:0:01:0:001\n%NPG\nN0000 G1\n");
    EXPECT_EQ(codes(noEnd), std::vector<std::string>{"DAT_MISSING_PROGRAMMENDE"});
    EXPECT_FALSE(noEnd.diagnostics.hasErrors());

    Program badParam = parse("id\n%MAC:0:03:0:019\n%MAC\n%CHBEGIN%\n%V% 141 INT\n%CHEND%\nRTS\n");
    EXPECT_NE(find(badParam, "DAT_BAD_CYCLE_PARAMETER"), nullptr);

    Program noChEnd = parse("id\n%MAC:0:03:0:019\n%MAC\n%CHBEGIN%\n%V% @1 INT\nN0000 RTS\n");
    EXPECT_NE(find(noChEnd, "DAT_UNTERMINATED_CYCLE_DECLARATIONS"), nullptr);
    EXPECT_EQ(noChEnd.blocks.size(), 1u);
}

TEST(DatFileLimits, SeventyOneCharactersAreFineSeventyTwoAreNot) {
    std::string head = "id\n%NPG:0:01:0:001\n%NPG\n";
    std::string ok = "N0000 G1 X1 ;" + std::string(71 - 13, 'c');
    std::string bad = "N0001 G1 X1 ;" + std::string(72 - 13, 'c');
    ASSERT_EQ(ok.size(), 71u);
    ASSERT_EQ(bad.size(), 72u);
    Program p = parse(head + ok + "\n" + bad + "\nN0002 PROGRAMMENDE\n");
    ASSERT_EQ(codes(p), std::vector<std::string>{"FILE_LINE_TOO_LONG"});
    const Diagnostic& d = p.diagnostics.items()[0];
    EXPECT_EQ(d.where.line, 5);
    EXPECT_EQ(d.where.column, 72);
    EXPECT_EQ(p.text(p.blocks[1].comment), std::string(72 - 13, 'c'));  // nothing is cut off
}

TEST(DatFileLimits, TenThousandLinesAreFineTenThousandAndOneAreNot) {
    auto make = [](int lines) {
        std::string text = "id\n%NPG:0:01:0:001\n%NPG\n";
        for (int i = 4; i < lines; ++i)
            text += "N" + std::to_string(1000 + i % 9000) + " G1\n";
        return text + "N0000 PROGRAMMENDE\n";
    };
    Program fine = parse(make(10000));
    EXPECT_TRUE(fine.diagnostics.empty());
    Program tooLong = parse(make(10001));
    ASSERT_EQ(codes(tooLong), std::vector<std::string>{"FILE_TOO_MANY_LINES"});
    EXPECT_EQ(tooLong.diagnostics.items()[0].where.line, 10001);
    EXPECT_EQ(tooLong.blocks.size(), 9998u);  // every block is still there
}

TEST(DatFileLimits, BlockLengthAndLineCount) {
    std::string head = "id\n%NPG:0:01:0:001\n%NPG\n";
    std::string fiveLines = "N0000 G1\n      X1\n      Y1\n      Z1\n      F1\n";
    Program p = parse(head + fiveLines + "N0001 PROGRAMMENDE\n");
    EXPECT_EQ(codes(p), std::vector<std::string>{"FILE_BLOCK_TOO_MANY_LINES"});
    std::string longBlock = "N0000 G1 ;" + std::string(60, 'a');
    for (int i = 0; i < 3; ++i)
        longBlock += "\n      " + std::string(64, 'b');
    Program q = parse(head + longBlock + "\nN0001 PROGRAMMENDE\n");
    EXPECT_EQ(codes(q), std::vector<std::string>{"FILE_BLOCK_TOO_LONG"});
}

TEST(DatFileLimits, LooseFilesHaveNoLimits) {
    std::string text = "N0000 G1 X1 ;" + std::string(500, 'c') + "\n";
    for (int i = 0; i < 10500; ++i)
        text += "G1 X1\n";
    Program p = parse(text);
    EXPECT_TRUE(p.diagnostics.empty());
    EXPECT_FALSE(p.hasDatHeader);
}

TEST(DatFileName, ParseAndFormat) {
    auto name = parseDatFileName("/some/dir/N1010001.DAT");
    ASSERT_TRUE(name);
    EXPECT_EQ(name->plant, 1);
    EXPECT_EQ(name->package, 1);
    EXPECT_EQ(name->process, 0);
    EXPECT_EQ(name->number, 1);
    auto hex = parseDatFileName("NF993099.dat");
    ASSERT_TRUE(hex);
    EXPECT_EQ(hex->plant, 15);
    EXPECT_EQ(hex->package, 99);
    EXPECT_EQ(hex->process, 3);
    EXPECT_EQ(hex->number, 99);
    EXPECT_EQ(formatDatFileName(*hex), "NF993099.DAT");
    EXPECT_EQ(formatDatFileName(DatFileName{0, 1, 0, 1}), "N0010001.DAT");
    EXPECT_EQ(formatDatFileName(DatFileName{0, 1, 7, 1}), "");
    std::string why;
    for (const char* bad :
         {"N1010001.NCO", "N101001.DAT", "X1010001.DAT", "NG010001.DAT", "N1000001.DAT",
          "N1017001.DAT", "N1010000.DAT", "N1010100.DAT", "N10A0001.DAT"}) {
        EXPECT_FALSE(parseDatFileName(bad, &why)) << bad;
        EXPECT_FALSE(why.empty()) << bad;
    }
}

TEST(DatFileIo, ReadWriteRoundTripIsByteIdentical) {
    TempDir dir("mtc-datfile");
    std::string path = dir.file("N1010007.DAT");
    writeWholeFile(path, kShaft);
    Program p = DatFile::read(path);
    ASSERT_TRUE(p.diagnostics.empty());
    EXPECT_EQ(p.number, 7);
    std::string copy = dir.file("N1010008.DAT");
    DiagnosticList diagnostics;
    ASSERT_TRUE(DatFile::write(copy, p, DatFileName{1, 1, 0, 8}, diagnostics));
    EXPECT_EQ(readWholeFile(copy), kShaft);
    Program again = DatFile::read(copy);
    EXPECT_EQ(again.blocks.size(), p.blocks.size());
    EXPECT_EQ(describeBlock(again, 1), describeBlock(p, 1));
}

TEST(DatFileIo, LooseProgramGetsHeaderAndProgramEnd) {
    Program loose = parse("N0000 G0 X0\nN0001 G1 X5 F100\n");
    loose.name = "bracket";
    std::string text = DatFile::format(loose, DatFileName{1, 1, 2, 12});
    Program p = DatFile::parse(text, "N1012012.DAT");
    ASSERT_TRUE(p.diagnostics.empty()) << formatDiagnostic(p.diagnostics.items()[0]);
    EXPECT_TRUE(p.hasDatHeader);
    EXPECT_EQ(p.title, "bracket");
    EXPECT_EQ(p.number, 12);
    ASSERT_EQ(p.blocks.size(), 3u);
    EXPECT_EQ(p.blockId(2), "N0002");
    EXPECT_TRUE(p.blocks[2].flags & kBlockProgramEnd);
    EXPECT_NE(p.header.find("%NPG:1:01:2:012"), std::string::npos);
}

TEST(DatFileIo, ReadingAFileWithErrorsKeepsEverything) {
    TempDir dir("mtc-datfile");
    std::string text =
        "id\n%NPG:1:01:0:003\n%NPG\nN0000 G1 H9\nN0001 G1 X5 " + std::string(80, 'Y') + "\n";
    writeWholeFile(dir.file("N1010003.DAT"), text);
    Program p = DatFile::read(dir.file("N1010003.DAT"));
    EXPECT_EQ(p.source, text);
    EXPECT_NE(find(p, "PARSE_UNKNOWN_WORD"), nullptr);
    EXPECT_NE(find(p, "FILE_LINE_TOO_LONG"), nullptr);
    EXPECT_NE(find(p, "DAT_MISSING_PROGRAMMENDE"), nullptr);
    EXPECT_EQ(p.blocks.size(), 2u);
}

TEST(DatFileIo, UnreadableFileAndNameMismatch) {
    Program missing = DatFile::read("/nonexistent/dir/N1010001.DAT");
    ASSERT_EQ(codes(missing), std::vector<std::string>{"FILE_UNREADABLE"});
    EXPECT_EQ(missing.number, 1);
    TempDir dir("mtc-datfile");
    Program directory = DatFile::read(dir.path().string());
    EXPECT_EQ(codes(directory), std::vector<std::string>{"FILE_UNREADABLE"});

    Program mismatch = DatFile::parse(kShaft, "N1010009.DAT");
    EXPECT_NE(find(mismatch, "DAT_NAME_MISMATCH"), nullptr);
    EXPECT_EQ(mismatch.number, 9);  // the file name decides
}

TEST(DatFileIo, ReadFileText) {
    TempDir dir("mtc-datfile");
    std::string text, error;
    std::string binary("N0000 G1\0\xff\n", 11);
    writeWholeFile(dir.file("a.DAT"), binary);
    ASSERT_TRUE(readFileText(dir.file("a.DAT"), text, error));
    EXPECT_EQ(text, binary);
    writeWholeFile(dir.file("empty.DAT"), "");
    ASSERT_TRUE(readFileText(dir.file("empty.DAT"), text, error));
    EXPECT_TRUE(text.empty());
    EXPECT_FALSE(readFileText(dir.file("missing.DAT"), text, error));
    EXPECT_FALSE(error.empty());
    EXPECT_FALSE(readFileText(dir.path().string(), text, error));
}

TEST(AtomicWrite, ReplacesTheFileAndLeavesNoTemporary) {
    TempDir dir("mtc-datfile");
    std::string path = dir.file("N1010001.DAT");
    writeWholeFile(path, "old content\n");
    fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
    std::string error;
    ASSERT_TRUE(writeFileAtomically(path, "new content\n", error)) << error;
    EXPECT_EQ(readWholeFile(path), "new content\n");
    EXPECT_EQ(fs::status(path).permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
    int files = 0;
    for (const auto& entry : fs::directory_iterator(dir.path())) {
        (void)entry;
        ++files;
    }
    EXPECT_EQ(files, 1);
}

TEST(AtomicWrite, FailureLeavesTheOldFile) {
    TempDir dir("mtc-datfile");
    std::string error;
    EXPECT_FALSE(writeFileAtomically(dir.file("missing/N1010001.DAT"), "x", error));
    EXPECT_FALSE(error.empty());
    // Renaming onto a directory fails: the directory stays, no temporary is left.
    fs::create_directory(dir.file("N1010002.DAT"));
    fs::create_directory(dir.file("N1010002.DAT/keep"));
    Program p = parse("G1\n");
    DiagnosticList diagnostics;
    EXPECT_FALSE(DatFile::write(dir.file("N1010002.DAT"), p, DatFileName{1, 1, 0, 2}, diagnostics));
    ASSERT_EQ(diagnostics.size(), 1u);
    EXPECT_EQ(diagnostics.items()[0].code, "FILE_WRITE_FAILED");
    EXPECT_TRUE(fs::is_directory(dir.file("N1010002.DAT/keep")));
    int files = 0;
    for (const auto& entry : fs::directory_iterator(dir.path())) {
        (void)entry;
        ++files;
    }
    EXPECT_EQ(files, 1);
}

TEST(ProgramLoaderTest, LoadsADirectory) {
    TempDir dir("mtc-datfile");
    writeWholeFile(dir.file("N1010007.DAT"), kShaft);
    writeWholeFile(dir.file("N1012005.DAT"),
                   "N0000 G1 X1\nN0001 H5\n");               // process 2, with an error
    writeWholeFile(dir.file("N2010007.DAT"), "N0000 G0\n");  // same process/number
    writeWholeFile(dir.file("N1030019.DAT"), "id\n%MAC:1:03:0:019\n%MAC\nN0000 .*CYC\nN0001 RTS\n");
    writeWholeFile(dir.file("notes.DAT"), "G1\n");
    writeWholeFile(dir.file("N1010001.ERR"), "ignored\n");
    ProgramStore store;
    ProgramLoader loader(store);
    EXPECT_EQ(loader.loadDirectory(dir.path().string()), 3u);
    ASSERT_NE(store.find(0, 7), nullptr);
    EXPECT_EQ(store.find(0, 7)->title, "Flange with bore");
    ASSERT_NE(store.find(2, 5), nullptr);
    EXPECT_NE(find(*store.find(2, 5), "PARSE_UNKNOWN_WORD"), nullptr);  // loaded with diagnostics
    ASSERT_EQ(store.cycles().count("N1030019"), 1u);
    EXPECT_EQ(store.cycles().at("N1030019")->findLabel("*CYC"), 0);
    std::vector<std::string> fileCodes;
    for (const auto& d : loader.diagnostics().items())
        fileCodes.push_back(d.code);
    EXPECT_EQ(fileCodes, (std::vector<std::string>{"FILE_DUPLICATE_PROGRAM", "FILE_BAD_NAME"}));
}

TEST(ProgramLoaderTest, LoadsEmbeddedTexts) {
    ProgramStore store;
    ProgramLoader loader(store);
    std::vector<std::pair<std::string, std::string>> files = {
        {"programs/N1010099.DAT", "N0000 .TOOL\nN0001 RTS\n"},
        {"programs/N1010001.DAT", kShaft},
    };
    EXPECT_EQ(loader.loadTexts(files), 2u);
    ASSERT_NE(store.library(0), nullptr);
    EXPECT_EQ(store.library(0)->findLabel("TOOL"), 0);
    ASSERT_NE(store.find(0, 1), nullptr);
    EXPECT_NE(find(*store.find(0, 1), "DAT_NAME_MISMATCH"), nullptr);
    EXPECT_TRUE(loader.diagnostics().empty());

    ProgramLoader missing(store);
    EXPECT_EQ(missing.loadDirectory("/nonexistent/programs"), 0u);
    EXPECT_EQ(missing.diagnostics().items()[0].code, "FILE_UNREADABLE");
}

TEST(ProgramLoaderTest, EmbeddedDemoProgramsLoadWithoutErrors) {
    std::vector<std::pair<std::string, std::string>> files;
    for (const std::string& name : mtc::resources::list("programs/"))
        files.emplace_back(name, std::string(mtc::resources::find(name)));
    ASSERT_FALSE(files.empty());
    ProgramStore store;
    ProgramLoader loader(store);
    EXPECT_EQ(loader.loadTexts(files), files.size());
    EXPECT_TRUE(loader.diagnostics().empty());
    for (const auto& [key, program] : store.programs()) {
        EXPECT_TRUE(program->hasDatHeader) << program->name;
        for (const auto& d : program->diagnostics.items())
            ADD_FAILURE() << program->name << ": " << formatDiagnostic(d);
        ASSERT_FALSE(program->blocks.empty());
        EXPECT_TRUE(program->blocks.back().flags & kBlockProgramEnd) << program->name;
    }
}

}  // namespace
