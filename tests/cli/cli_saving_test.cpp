// Commands save like the io layer promises (docs/files.md, Saving), seen from the command line: render's
// PNG and refine's OBJ go to what the user named, refusals and failures exit 3 with a message that
// names the file and the reason, and the old file stays with no temporary file beside it, also
// when the save is interrupted.
#include <csignal>
#include <filesystem>
#include <string>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "obj_test_support.h"
#include "run_rgbsub.h"
#include "scratch_folder.h"

namespace {

namespace fs = std::filesystem;

class CliSaving : public rgbio::test::ScratchFolder {
protected:
    void SetUp() override {
        ScratchFolder::SetUp();
        write("mesh.obj", rgbio::test::kOctahedron);
    }
    bool printed(const cli_test::Outcome& run, const std::string& text) const { return run.output.find(text) != std::string::npos; }
};

TEST_F(CliSaving, RenderToAFolderOrAnEmptyNameSaysWhy) {
    fs::create_directory(folder_ / "pictures");
    const cli_test::Outcome to_folder = cli_test::run_rgbsub({"render", path("mesh.obj"), "-o", path("pictures")});
    EXPECT_EQ(to_folder.exit_code, 3);
    EXPECT_EQ(to_folder.output, "rgbsub render: cannot save " + path("pictures") + ": it is a folder; rgbsub saves only to regular files\n");
    EXPECT_TRUE(fs::is_empty(folder_ / "pictures"));
    const cli_test::Outcome empty = cli_test::run_rgbsub({"render", path("mesh.obj"), "-o", ""});
    EXPECT_EQ(empty.exit_code, 3);
    EXPECT_EQ(empty.output, "rgbsub render: cannot save '': the file name is empty\n");
    EXPECT_EQ(entries(), 2u);
}

// The PNG is checked write by write: under a file-size limit (a full disk) the old image stays.
TEST_F(CliSaving, RenderOnAFullDiskKeepsTheOldImage) {
    write("picture.png", "the old picture");
    const cli_test::Outcome run = cli_test::run_rgbsub({"render", path("mesh.obj"), "-o", path("picture.png")}, "ulimit -f 1;");
    EXPECT_EQ(run.exit_code, 3);
    EXPECT_EQ(run.output, "rgbsub render: cannot save " + path("picture.png") + ": write failed: File too large\n");
    EXPECT_EQ(read(path("picture.png")), "the old picture");
    EXPECT_EQ(entries(), 2u) << "a temporary file was left behind";
}

TEST_F(CliSaving, RenderWritesThroughASymbolicLink) {
    fs::create_symlink("real.png", folder_ / "link.png");
    ASSERT_EQ(cli_test::run_rgbsub({"render", path("mesh.obj"), "-o", path("link.png"), "--size", "32x24"}).exit_code, 0);
    EXPECT_TRUE(fs::is_symlink(path("link.png")));
    EXPECT_EQ(read(path("real.png")).substr(1, 3), "PNG");
}

// A FIFO would block a writer forever (or a device entry would be replaced): refused at once.
TEST_F(CliSaving, RefineToAFifoIsRefused) {
    ASSERT_EQ(::mkfifo(path("pipe").c_str(), 0644), 0);
    const cli_test::Outcome run = cli_test::run_rgbsub({"refine", path("mesh.obj"), "-o", path("pipe"), "--level", "1"});
    EXPECT_EQ(run.exit_code, 3);
    EXPECT_EQ(run.output, "rgbsub refine: cannot save " + path("pipe") + ": it is a FIFO (named pipe); rgbsub saves only to regular files\n");
    EXPECT_TRUE(fs::is_fifo(path("pipe")));
}

TEST_F(CliSaving, LegalLongOutputNamesSave) {
    // Appended rather than `std::string(246, 'a') + ".obj"`: g++ 12 at -O3 warns falsely that this
    // operator+ copies out of bounds (-Warray-bounds, a known GCC 12 false positive).
    std::string name(246, 'a');
    name += ".obj";  // 250 bytes
    const cli_test::Outcome run = cli_test::run_rgbsub({"refine", path("mesh.obj"), "-o", path(name), "--level", "1"});
    EXPECT_EQ(run.exit_code, 0) << run.output;
    EXPECT_EQ(cli_test::run_rgbsub({"info", path(name)}).exit_code, 0);
    EXPECT_EQ(entries(), 2u);
}

// `-o -o` once wrote a file named "--output"; now it is a usage error that writes nothing.
TEST_F(CliSaving, OptionAsOutputNameWritesNothing) {
    const cli_test::Outcome run = cli_test::run_rgbsub({"refine", path("mesh.obj"), "--level", "1", "-o", "-o"});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_TRUE(printed(run, "-o/--output needs a value, but the next word is the option '-o'")) << run.output;
    EXPECT_EQ(entries(), 1u);
}

// Ctrl+C (or a kill) while refine writes its file: the temporary file goes, the old file stays, and
// the process dies of the signal as a shell expects. The child is watched until its temporary file
// exists (the 940k-triangle save takes a good part of a second), then signalled.
TEST_F(CliSaving, InterruptedSaveLeavesNoTemporaryFile) {
    for (int signal : {SIGINT, SIGTERM}) {
        write("fine.obj", "the old file\n");
        const std::string bunny = std::string(RGBSUB_SOURCE_DIR) + "/assets/bunny.obj";
        const std::string output = path("fine.obj");
        const pid_t pid = ::fork();
        if (pid == 0) {
            ::execl(RGBSUB_BINARY, "rgbsub", "refine", bunny.c_str(), "-o", output.c_str(), "--level", "4", static_cast<char*>(nullptr));
            ::_exit(127);
        }
        bool seen = false;
        for (int i = 0; i < 60000 && !seen; ++i) {  // up to a minute
            for (const auto& entry : fs::directory_iterator(folder_)) seen |= entry.path().filename().string().starts_with("fine.obj.tmp-");
            if (!seen) ::usleep(1000);
        }
        ASSERT_TRUE(seen) << "the save's temporary file never appeared";
        ::kill(pid, signal);
        int status = 0;
        ::waitpid(pid, &status, 0);
        if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
            EXPECT_EQ(entries(), 2u) << "the save finished before the signal, and left a temporary file";
            continue;  // the save won the race: nothing to check about the signal
        }
        ASSERT_TRUE(WIFSIGNALED(status)) << "exit code " << WEXITSTATUS(status);
        EXPECT_EQ(WTERMSIG(status), signal);
        EXPECT_EQ(read(output), "the old file\n");
        EXPECT_EQ(entries(), 2u) << "signal " << signal << " left a temporary file";
    }
}

}  // namespace
