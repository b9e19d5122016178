// The file-backed program text (PROC-003): a program parsed from its file
// chunk by chunk is the program parsed from the whole text; its text is not
// resident after the parse, comes back from the file where it is read, and a
// file changed or cut short on disk reads as blanks with a message naming
// the file, never as another text and never as a crash (SIGBUS).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "cnc_core/language/Parser.h"
#include "cnc_core/program/DatFile.h"
#include "cnc_core/program/FileBackedText.h"
#include "tests/support/ProgramDifference.h"
#include "tests/support/TempDir.h"

namespace mtc::core {
namespace {

constexpr std::uint32_t kChunk = FileBackedText::kChunkBytes;

void writeFile(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

/// A loose program of about `bytes` bytes with plain moves, labels, jumps,
/// comments, continuation lines, a DEFINE macro, command words and a line
/// longer than a chunk (the window must hold whole lines and pending blocks).
std::string mixedProgram(std::size_t bytes) {
    std::string text = "N0000 DEFINE FAST AS G0\nN0001 G1 X0 Y0 F900 ;start\n";
    for (int n = 2; text.size() < bytes; ++n) {
        const std::string number = "N" + std::to_string(1000 + n % 9000);
        switch (n % 97) {
            case 0:
                text += ".L" + std::to_string(n) + " " + number + " G1 X1.5 Y2\n";
                break;
            case 1:
                text += number + " BRA .L" + std::to_string(n - 1) + "\n";
                break;
            case 2:
                text += number + " G1 X3 Y4\n      Z5 F300 ;continued\n";
                break;
            case 3:
                text += number + " FAST X7 Y8\n";
                break;
            case 4:
                text += number + " (tool) M6 T3 ;" + std::string(200, 'c') + "\n";
                break;
            case 5:
                text += "\n; a comment line\n";
                break;
            default:
                text += number + " G1 X" + std::to_string(n % 400) + ".125 Y-" +
                        std::to_string(n % 300) + ".5\n";
        }
        if (n == 40000) text += "; " + std::string(3 * kChunk, 'x') + "\n";
    }
    return text;
}

std::shared_ptr<FileBackedText> openText(const std::string& path) {
    std::string error;
    auto file = FileBackedText::open(path, error);
    EXPECT_TRUE(file) << error;
    return file;
}

class FileBackedTextTest : public ::testing::Test {
  protected:
    /// Parses `text` from a file (file-backed) and from the string.
    void parseBoth(const std::string& text, const std::string& name = "big.nc") {
        path_ = dir_.file(name);
        writeFile(path_, text);
        file_ = openText(path_);
        fromFile_ = DatFile::parse(SourceText(file_), name);
        fromString_ = DatFile::parse(text, name);
    }

    test::TempDir dir_{"mtc-filetext"};
    std::string path_;
    std::shared_ptr<FileBackedText> file_;
    Program fromFile_, fromString_;
};

TEST_F(FileBackedTextTest, ParsesLikeTheWholeText) {
    const std::string text = mixedProgram(6u << 20);
    parseBoth(text);
    EXPECT_EQ(testing::programDifference(fromFile_, fromString_), "");
    EXPECT_GT(fromFile_.blocks.size(), 100000u);
    EXPECT_FALSE(fromFile_.labels.empty());
    EXPECT_EQ(fromFile_.source.size(), text.size());
    EXPECT_FALSE(file_->changed());
}

TEST_F(FileBackedTextTest, TheCountsBeforeTheParseLeaveTheTextOnDisk) {
    // PROC-004: the counts come from a small buffer; the text is read into
    // memory only ahead of the parse's scanner.
    const std::string text = mixedProgram(3u << 20);
    path_ = dir_.file("counted.nc");
    writeFile(path_, text);
    file_ = openText(path_);
    std::size_t lines = 1, blanks = 0, expectedLines = 1, expectedBlanks = 0;
    file_->countLinesAndBlanks(lines, blanks);
    countLinesAndBlanks(text, expectedLines, expectedBlanks);
    EXPECT_EQ(lines, expectedLines);
    EXPECT_EQ(blanks, expectedBlanks);
    EXPECT_EQ(file_->residentBytes(), 0u);
    EXPECT_FALSE(file_->changed());
}

TEST_F(FileBackedTextTest, TextIsNotResidentAfterTheParse) {
    parseBoth(mixedProgram(6u << 20));
    EXPECT_EQ(file_->residentBytes(), 0u);
}

TEST_F(FileBackedTextTest, TextReadAgainOnDemandEqualsTheFile) {
    const std::string text = mixedProgram(3u << 20);
    parseBoth(text);
    const std::size_t last = fromFile_.blocks.size() - 1;
    for (std::size_t i : {std::size_t{0}, last / 3, last / 2, last}) {
        const TextSpan span = fromFile_.blocks[i].sourceText;
        EXPECT_EQ(fromFile_.text(span), text.substr(span.offset, span.length)) << i;
    }
    EXPECT_LE(file_->residentBytes(), 5u * kChunk);  // only the chunks read
    EXPECT_EQ(fromFile_.source.view(), text);        // the whole text, e.g. to save it
    EXPECT_EQ(file_->residentBytes(), text.size());
    EXPECT_FALSE(file_->changed());
    EXPECT_EQ(file_->changeMessage(), "");
}

TEST_F(FileBackedTextTest, EveryGoldenAndDemoProgramParsesAlike) {
    namespace fs = std::filesystem;
    int files = 0;
    for (const char* folder : {"/tests/golden", "/resources/programs"})
        for (const auto& entry :
             fs::recursive_directory_iterator(MTC_SOURCE_DIR + std::string(folder))) {
            const std::string name = entry.path().filename().string();
            const std::string ext = entry.path().extension().string();
            if (!entry.is_regular_file() || (ext != ".nc" && ext != ".DAT")) continue;
            parseBoth(test::readWholeFile(entry.path().string()), name);
            EXPECT_EQ(testing::programDifference(fromFile_, fromString_), "") << entry.path();
            EXPECT_EQ(fromFile_.header, fromString_.header) << entry.path();
            EXPECT_EQ(fromFile_.identification, fromString_.identification) << entry.path();
            EXPECT_EQ(fromFile_.hasDatHeader, fromString_.hasDatHeader) << entry.path();
            ++files;
        }
    EXPECT_GT(files, 40);
}

TEST_F(FileBackedTextTest, ALineLongerThanAChunkAndNoFinalNewline) {
    parseBoth("N0001 G1 X1 ;" + std::string(5 * kChunk / 2, 'a') + "\nN0002 G1 X2 Y" +
              std::string(2 * kChunk, '7'));
    EXPECT_EQ(testing::programDifference(fromFile_, fromString_), "");
    parseBoth("");
    EXPECT_EQ(testing::programDifference(fromFile_, fromString_), "");
}

TEST_F(FileBackedTextTest, AFileChangedOnDiskReadsAsBlanksAndSaysSo) {
    const std::string text = mixedProgram(2u << 20);
    parseBoth(text);
    std::string edited = text;
    for (char& c : edited)
        if (c == '5') c = '6';
    {
        std::fstream inPlace(path_, std::ios::in | std::ios::out | std::ios::binary);
        inPlace.write(edited.data(), static_cast<std::streamsize>(edited.size()));
    }  // an editor saving in place: same inode, same size
    const TextSpan span = fromFile_.blocks[fromFile_.blocks.size() / 2].sourceText;
    EXPECT_EQ(fromFile_.text(span), std::string(span.length, ' '));
    EXPECT_TRUE(file_->changed());
    EXPECT_NE(file_->changeMessage().find(path_), std::string::npos) << file_->changeMessage();
    EXPECT_NE(file_->changeMessage().find("changed on disk"), std::string::npos);
}

TEST_F(FileBackedTextTest, AFileCutShortReadsAsBlanksWithoutACrash) {
    const std::string text = mixedProgram(2u << 20);
    parseBoth(text);
    ASSERT_EQ(::truncate(path_.c_str(), 4096), 0);
    const TextSpan span = fromFile_.blocks.back().sourceText;
    EXPECT_EQ(fromFile_.text(span), std::string(span.length, ' '));
    EXPECT_TRUE(file_->changed());
    EXPECT_NE(file_->changeMessage().find(path_), std::string::npos);
}

TEST_F(FileBackedTextTest, AFileCutShortBeforeTheParseParsesItsBlanksAndSaysSo) {
    const std::string text = mixedProgram(1u << 20);
    path_ = dir_.file("cut.nc");
    writeFile(path_, text);
    file_ = openText(path_);
    ASSERT_EQ(::truncate(path_.c_str(), 100000), 0);
    const Program program = parseProgram(SourceText(file_));
    const Program head =
        parseProgram(text.substr(0, 100000) + std::string(text.size() - 100000, ' '));
    EXPECT_EQ(testing::programDifference(program, head), "");
    EXPECT_TRUE(file_->changed());
}

TEST_F(FileBackedTextTest, ThreadsReadTheTextAgainTogether) {
    const std::string text = mixedProgram(2u << 20);
    parseBoth(text);
    std::vector<std::thread> readers;
    std::vector<int> equal(4, 0);
    for (int t = 0; t < 4; ++t)
        readers.emplace_back([&, t] { equal[t] = fromFile_.source.view() == text; });
    for (std::thread& reader : readers)
        reader.join();
    EXPECT_EQ(equal, std::vector<int>(4, 1));
    EXPECT_FALSE(file_->changed());
}

TEST_F(FileBackedTextTest, ASecondParseOfTheSameTextReadsItWhole) {
    const std::string text = mixedProgram(1u << 20);
    parseBoth(text);
    const Program again = parseProgram(fromFile_.source);
    EXPECT_EQ(testing::programDifference(again, fromString_), "");
}

TEST(FileBackedTextOpen, RefusesWhatIsNotARegularFile) {
    std::string error;
    EXPECT_FALSE(FileBackedText::open("/nonexistent/x.nc", error));
    EXPECT_NE(error.find("does not exist"), std::string::npos) << error;
    EXPECT_FALSE(FileBackedText::open("/tmp", error));
    EXPECT_NE(error.find("is a directory"), std::string::npos) << error;
}

TEST(ChunkHash, SeesEveryByte) {
    std::string text(1000, 'a');
    const std::uint64_t before = chunkHash(text.data(), text.size());
    for (std::size_t i : {0u, 7u, 31u, 32u, 500u, 996u, 999u}) {
        std::string changed = text;
        changed[i] = 'b';
        EXPECT_NE(chunkHash(changed.data(), changed.size()), before) << i;
    }
    EXPECT_NE(chunkHash(text.data(), 999), before);
}

}  // namespace
}  // namespace mtc::core
