// The info/refine/apply subcommands through the dispatcher: exit codes 0/1/2/3 and apply's scripts
// (refine itself: tests/cli/refine_command_test.cpp).
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "cli/dispatch.h"
#include "io/obj_reader.h"
#include "obj_test_support.h"

namespace rgbio {
namespace {

namespace fs = std::filesystem;

class CliCommands : public ::testing::Test {
protected:
    void SetUp() override {
        folder_ = fs::temp_directory_path() / ("rgbsub_cli_" + std::to_string(::getpid()) + "_" +
                                               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(folder_);
        fs::create_directories(folder_);
        write("octahedron.obj", test::kOctahedron);
    }
    void TearDown() override { fs::remove_all(folder_); }
    std::string path(const std::string& name) const { return (folder_ / name).string(); }
    void write(const std::string& name, const std::string& text) const { std::ofstream(folder_ / name, std::ios::binary) << text; }
    static int run(std::vector<std::string> args) { return cli::dispatch(args); }
    fs::path folder_;
};

TEST_F(CliCommands, ExitCodes) {
    EXPECT_EQ(run({"info", path("octahedron.obj")}), 0);
    EXPECT_EQ(run({"info", "--help"}), 0);
    EXPECT_EQ(run({"refine", "--help"}), 0);
    EXPECT_EQ(run({"apply", "--help"}), 0);
    EXPECT_EQ(run({"info"}), 1);
    EXPECT_EQ(run({"refine", path("octahedron.obj"), "--level", "2"}), 1);                           // no -o
    EXPECT_EQ(run({"refine", path("octahedron.obj"), "-o", path("o.obj"), "--level", "x"}), 1);
    EXPECT_EQ(run({"refine", path("octahedron.obj"), "-o", path("o.obj"), "--level", "1", "--sphere", "1,2"}), 1);
    EXPECT_EQ(run({"refine", path("octahedron.obj"), "-o", path("o.obj"), "--level", "1", "--positions", "x"}), 1);
    write("bowtie.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv -1 0 0\nv -1 -1 0\nf 1 2 3\nf 1 4 5\n");
    EXPECT_EQ(run({"info", path("bowtie.obj")}), 2);
    EXPECT_EQ(run({"info", path("missing.obj")}), 3);
    EXPECT_EQ(run({"refine", path("octahedron.obj"), "-o", path("octahedron.obj/x.obj"), "--level", "1"}), 3);
    write("script.txt", "level 2\nlevel 3 sphere 1 0 0 0.5\nbogus\n");
    EXPECT_EQ(run({"apply", path("octahedron.obj"), path("script.txt"), "-o", path("o.obj")}), 2);
    EXPECT_FALSE(fs::exists(path("o.obj")));
    EXPECT_EQ(run({"apply", path("octahedron.obj"), path("missing.txt"), "-o", path("o.obj")}), 3);
}

TEST_F(CliCommands, ApplyRunsTheScriptLikeRefine) {
    write("script.txt", "# comment\nlevel 2\n\nlevel 4 sphere 1 0 0 0.5\n");
    ASSERT_EQ(run({"apply", path("octahedron.obj"), path("script.txt"), "-o", path("applied.obj")}), 0);
    ASSERT_EQ(run({"refine", path("octahedron.obj"), "-o", path("step.obj"), "--level", "2"}), 0);
    ASSERT_EQ(run({"refine", path("step.obj"), "-o", path("refined.obj"), "--level", "4", "--sphere", "1,0,0,0.5"}), 0);
    const LoadedMesh applied = read_obj_file(path("applied.obj"));
    const LoadedMesh refined = read_obj_file(path("refined.obj"));
    EXPECT_EQ(applied.positions, refined.positions);
    EXPECT_EQ(applied.triangles, refined.triangles);
}

// Every operation on a closed mesh changes the triangle count by exactly two, and the driver refines
// until the count reaches the budget and trims back down to it, so an even budget is met exactly.
TEST_F(CliCommands, ApplyBudgetMeetsTheTriangleCountExactly) {
    write("script.txt", "budget 500\n");
    ASSERT_EQ(run({"apply", path("octahedron.obj"), path("script.txt"), "-o", path("budget.obj")}), 0);
    const LoadedMesh fine = read_obj_file(path("budget.obj"));
    ASSERT_TRUE(fine.state);
    EXPECT_EQ(fine.triangles.size(), 500u);
    write("down.txt", "level 4\nbudget 100\n");
    ASSERT_EQ(run({"apply", path("octahedron.obj"), path("down.txt"), "-o", path("down.obj")}), 0);
    EXPECT_EQ(read_obj_file(path("down.obj")).triangles.size(), 100u);
    write("bad.txt", "budget lots\n");
    EXPECT_EQ(run({"apply", path("octahedron.obj"), path("bad.txt"), "-o", path("bad.obj")}), 2);
}

}  // namespace
}  // namespace rgbio
