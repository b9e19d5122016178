// Files are never clobbered (issue 22 §3, docs/decisions/config-files.md
// CF-010..CF-014): the one atomic write refuses what is not a regular file,
// writes through a symbolic link, refuses a read-only file; compile refuses
// an output that is its source; the .NCO/.ERR pair never mixes two compiles,
// even when the writer is killed; stale temporaries of a program directory
// are removed on load; a folder or FIFO named *.DAT is reported.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <utime.h>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "KillDuringWork.h"
#include "cnc_core/compiler/CompilerFiles.h"
#include "cnc_core/program/AtomicWrite.h"
#include "cnc_core/program/ProgramLoader.h"
#include "tests/support/TempDir.h"

namespace {

using namespace mtc::core;
namespace fs = std::filesystem;

class FileSafety : public ::testing::Test {
  protected:
    std::string file(const std::string& name) const { return dir_.file(name); }
    static std::string read(const std::string& path) { return mtc::test::readWholeFile(path); }
    static void write(const std::string& path, const std::string& text) {
        mtc::test::writeWholeFile(path, text);
    }
    mtc::test::TempDir dir_{"mtc-files"};
};

TEST_F(FileSafety, ATargetThatIsNoRegularFileIsRefused) {
    std::string error;
    ASSERT_EQ(::mkfifo(file("pipe.NCO").c_str(), 0644), 0);
    EXPECT_FALSE(writeFileAtomically(file("pipe.NCO"), "data", error));
    EXPECT_NE(error.find("FIFO"), std::string::npos) << error;
    EXPECT_TRUE(fs::is_fifo(file("pipe.NCO"))) << "the FIFO is still a FIFO";
    fs::create_directory(file("folder.DAT"));
    EXPECT_FALSE(writeFileAtomically(file("folder.DAT"), "data", error));
    EXPECT_NE(error.find("directory"), std::string::npos) << error;
    EXPECT_TRUE(fs::is_directory(file("folder.DAT")));
    // A device is refused by the same check (not written to: it would be
    // replaced on a machine where the test runs as root if the check failed).
    EXPECT_FALSE(checkReplaceable("/dev/null", error));
    EXPECT_NE(error.find("device"), std::string::npos) << error;
    for (const auto& entry : fs::directory_iterator(dir_.path()))
        EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos)
            << "no temporary left: " << entry.path();
}

TEST_F(FileSafety, ASymbolicLinkIsWrittenThroughToItsRealFile) {
    fs::create_directory(file("real"));
    write(file("real/cell.mdt"), "old");
    fs::create_symlink(file("real/cell.mdt"), file("link.mdt"));
    std::string error;
    ASSERT_TRUE(writeFileAtomically(file("link.mdt"), "new", error)) << error;
    EXPECT_TRUE(fs::is_symlink(file("link.mdt"))) << "the link stays a link";
    EXPECT_EQ(read(file("real/cell.mdt")), "new") << "the real file has the new content";
    // A link to a file that is not there yet: the file is made where it points.
    fs::create_symlink("real/later.mdt", file("later.mdt"));
    ASSERT_TRUE(writeFileAtomically(file("later.mdt"), "made", error)) << error;
    EXPECT_EQ(read(file("real/later.mdt")), "made");
    EXPECT_TRUE(fs::is_symlink(file("later.mdt")));
    // Removing through the link removes the real file, the link stays.
    ASSERT_TRUE(removeFile(file("later.mdt"), error)) << error;
    EXPECT_FALSE(fs::exists(file("real/later.mdt")));
    EXPECT_TRUE(fs::is_symlink(file("later.mdt")));
    // Into a missing directory, or a loop: refused.
    fs::create_symlink(file("nowhere/x"), file("dangling.mdt"));
    EXPECT_FALSE(writeFileAtomically(file("dangling.mdt"), "new", error));
    EXPECT_TRUE(fs::is_symlink(file("dangling.mdt")));
    fs::create_symlink(file("loop2"), file("loop1"));
    fs::create_symlink(file("loop1"), file("loop2"));
    EXPECT_FALSE(writeFileAtomically(file("loop1"), "new", error));
    EXPECT_NE(error.find("loop"), std::string::npos) << error;
}

TEST_F(FileSafety, AReadOnlyFileIsNotReplaced) {
    write(file("N1010001.DAT"), "program");
    fs::permissions(file("N1010001.DAT"),
                    fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
    std::string error;
    EXPECT_FALSE(writeFileAtomically(file("N1010001.DAT"), "other", error));
    EXPECT_NE(error.find("read-only"), std::string::npos) << error;
    EXPECT_EQ(read(file("N1010001.DAT")), "program");
    write(file("keep.mdt"), "old");
    fs::permissions(file("keep.mdt"), fs::perms::owner_read | fs::perms::owner_write);
    ASSERT_TRUE(writeFileAtomically(file("keep.mdt"), "new", error)) << error;
    EXPECT_EQ(fs::status(file("keep.mdt")).permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write)
        << "the mode of the replaced file is kept";
}

CompileResult compiled(const std::string& object) {
    CompileResult r;
    r.status = CompileStatus::Compiled;
    r.objectText = object;
    return r;
}

CompileResult failed(const std::string& message) {
    CompileResult r;
    r.status = CompileStatus::Error;
    CompilerError e;
    e.block = "N0001";
    e.message = message;
    r.errors.push_back(e);
    return r;
}

TEST_F(FileSafety, CompileRefusesToWriteOverItsSource) {
    write(file("X.DAT"), "N0001 G1 X1\n");
    std::string errorPath, error;
    EXPECT_FALSE(
        writeCompileFiles(file("X.DAT"), file("X.DAT"), compiled("object\n"), errorPath, error));
    EXPECT_NE(error.find("source program itself"), std::string::npos) << error;
    EXPECT_EQ(read(file("X.DAT")), "N0001 G1 X1\n");
    // The same file under another name: a link, or a path with ./ in it.
    fs::create_symlink(file("X.DAT"), file("Y.NCO"));
    EXPECT_FALSE(
        writeCompileFiles(file("X.DAT"), file("Y.NCO"), compiled("object\n"), errorPath, error));
    EXPECT_FALSE(writeCompileFiles(file("X.DAT"), (dir_.path() / "." / "X.DAT").string(),
                                   compiled("o\n"), errorPath, error));
    fs::create_hard_link(file("X.DAT"), file("Z.ERR"));
    EXPECT_FALSE(writeCompileFiles(file("X.DAT"), file("Z.NCO"), failed("bad"), errorPath, error))
        << "the error file would be the source";
    EXPECT_EQ(read(file("X.DAT")), "N0001 G1 X1\n");
    ASSERT_TRUE(writeCompileFiles(file("X.DAT"), "", compiled("object\n"), errorPath, error))
        << error;
    EXPECT_EQ(read(file("X.NCO")), "object\n");
}

/// Compiles forever, alternating results whose files carry their generation.
[[noreturn]] void compileForever(const std::string& source, int steps) {
    std::string errorPath, error;
    for (long generation = 1;; ++generation) {
        const std::string tag = "generation " + std::to_string(generation);
        CompileResult r = generation % 3 == 0 ? failed(tag) : compiled(tag + "\n");
        if (r.status == CompileStatus::Compiled) {  // with a warning: still no .ERR (C-014)
            CompilerError warning;
            warning.severity = Severity::Warning;
            warning.block = "N0001";
            warning.message = tag;
            r.errors.push_back(warning);
        }
        if (!writeCompileFiles(source, "", r, errorPath, error)) ::_exit(3);
        mtc::test::stepDone(steps);
        ::usleep(3000);  // finished states are as likely to be hit as the ones between
    }
}

/// The generation named in a compile file ("" when it has none).
std::string generationIn(const std::string& text) {
    const std::size_t at = text.find("generation ");
    if (at == std::string::npos) return "";
    return text.substr(at, text.find('\n', at) - at);
}

TEST_F(FileSafety, AKilledCompileNeverLeavesAnObjectBesideAnotherCompilesErrors) {
    write(file("P.DAT"), "N0001 G1 X1\n");
    std::mt19937 random(22);
    std::uniform_int_distribution<int> delay(200, 20000);
    int objects = 0, errorFiles = 0;
    for (int attempt = 0; attempt < 30; ++attempt) {
        ASSERT_TRUE(mtc::test::killDuringWork(
            [&](int steps) { compileForever(file("P.DAT"), steps); }, delay(random)))
            << "the compiling child never finished a compile";
        const bool object = fs::exists(file("P.NCO")), errors = fs::exists(file("P.ERR"));
        // A compile writes either an object file or an error file (C-014);
        // the other one of an earlier compile is gone before it (CF-013).
        EXPECT_FALSE(object && errors)
            << "attempt " << attempt << ": object file " << generationIn(read(file("P.NCO")))
            << " beside the errors of " << generationIn(read(file("P.ERR")));
        objects += object;
        errorFiles += errors;
    }
    std::cout << "[ measured ] 30 kills: " << objects << " times an object file, " << errorFiles
              << " times an error file, never both\n";
    EXPECT_GT(objects + errorFiles, 0) << "no compile ever finished: the test proved nothing";
}

void age(const std::string& path, long seconds) {
    const std::time_t when = std::time(nullptr) - seconds;
    utimbuf times{when, when};
    ASSERT_EQ(::utime(path.c_str(), &times), 0);
}

TEST_F(FileSafety, TheProgramDirectoryIsCleanedAndOddEntriesAreReported) {
    write(file("N1010001.DAT"), "N0001 G1 X1\nN0002 M30\n");
    write(file("N1010001.DAT.tmpAb12Cd"), "half a sav");
    age(file("N1010001.DAT.tmpAb12Cd"), 3600);
    write(file("N1010001.NCO.tmpXy34Zw"), "half");
    age(file("N1010001.NCO.tmpXy34Zw"), 3600);
    write(file("N1010002.DAT.tmpYoung1"), "a save running now");
    write(file("notes.txt.tmpAb12Cd"), "not ours");
    age(file("notes.txt.tmpAb12Cd"), 3600);
    fs::create_directory(file("N1010003.DAT"));
    ASSERT_EQ(::mkfifo(file("N1010004.DAT").c_str(), 0644), 0);
    ProgramStore store;
    ProgramLoader loader(store);
    EXPECT_EQ(loader.loadDirectory(dir_.path().string()), 1u);
    EXPECT_FALSE(fs::exists(file("N1010001.DAT.tmpAb12Cd")));
    EXPECT_FALSE(fs::exists(file("N1010001.NCO.tmpXy34Zw")));
    EXPECT_TRUE(fs::exists(file("N1010002.DAT.tmpYoung1")));
    EXPECT_TRUE(fs::exists(file("notes.txt.tmpAb12Cd")));
    std::string messages;
    int stale = 0, odd = 0;
    for (const Diagnostic& d : loader.diagnostics().items()) {
        messages += formatDiagnostic(d) + "\n";
        stale += d.code == "FILE_STALE_TEMPORARY";
        odd += d.code == "FILE_UNREADABLE";
    }
    EXPECT_EQ(stale, 2) << messages;
    EXPECT_EQ(odd, 2) << messages;
    EXPECT_NE(messages.find("N1010003.DAT is a directory"), std::string::npos) << messages;
    EXPECT_NE(messages.find("N1010004.DAT is a FIFO"), std::string::npos) << messages;
}

}  // namespace
