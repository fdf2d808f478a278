// Commands save like the io layer promises (README, Saving), seen from the command line: render's
// PNG and refine's OBJ go to what the user named, refusals and failures exit 3 with a message that
// names the file and the reason, and the old file stays with no temporary file beside it.
#include <filesystem>
#include <string>

#include <sys/stat.h>

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
    const std::string name = std::string(246, 'a') + ".obj";  // 250 bytes
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

}  // namespace
