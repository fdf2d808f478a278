// The info/refine/apply subcommands through the dispatcher: exit codes 0/1/2/3, and refine then
// `--level 0` gives back the input mesh exactly.
#include <algorithm>
#include <filesystem>
#include <set>

#include <sys/resource.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "cli/dispatch.h"
#include "io/obj_reader.h"
#include "obj_test_support.h"
#include "scratch_folder.h"

namespace rgbio {
namespace {

namespace fs = std::filesystem;

class CliCommands : public test::ScratchFolder {
protected:
    void SetUp() override {
        ScratchFolder::SetUp();
        write("octahedron.obj", test::kOctahedron);
    }
    static int run(std::vector<std::string> args) { return cli::dispatch(args); }
};

// Triangles as triples of positions, rotated to start at the smallest, so that meshes can be
// compared regardless of vertex and face numbering.
using PositionTriangle = std::array<std::array<double, 3>, 3>;
std::multiset<PositionTriangle> triangles_by_position(const LoadedMesh& mesh) {
    std::multiset<PositionTriangle> set;
    for (const rgb::Triangle& t : mesh.triangles) {
        PositionTriangle p;
        for (int i = 0; i < 3; ++i) p[i] = {mesh.positions[t[i]].x, mesh.positions[t[i]].y, mesh.positions[t[i]].z};
        std::rotate(p.begin(), std::min_element(p.begin(), p.end()), p.end());
        set.insert(p);
    }
    return set;
}

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
    EXPECT_EQ(run({"info", path("bowtie.obj")}), 0);  // repaired, with a warning
    EXPECT_EQ(run({"info", path("bowtie.obj"), "--strict"}), 2);
    EXPECT_EQ(run({"info", path("missing.obj")}), 3);
    EXPECT_EQ(run({"refine", path("octahedron.obj"), "-o", path("octahedron.obj/x.obj"), "--level", "1"}), 3);
    write("script.txt", "level 2\nlevel 3 sphere 1 0 0 0.5\nbogus\n");
    EXPECT_EQ(run({"apply", path("octahedron.obj"), path("script.txt"), "-o", path("o.obj")}), 2);
    EXPECT_FALSE(fs::exists(path("o.obj")));
    EXPECT_EQ(run({"apply", path("octahedron.obj"), path("missing.txt"), "-o", path("o.obj")}), 3);
}

// Every command that reads a mesh refuses a non-manifold one with --strict (before any rendering or
// window), and repairs it without.
TEST_F(CliCommands, StrictRefusesNonManifoldInputInEveryCommand) {
    write("bowtie.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv -1 0 0\nv -1 -1 0\nf 1 2 3\nf 1 4 5\n");
    write("script.txt", "level 1\n");
    EXPECT_EQ(run({"refine", path("bowtie.obj"), "-o", path("o.obj"), "--level", "1", "--strict"}), 2);
    EXPECT_EQ(run({"apply", path("bowtie.obj"), path("script.txt"), "-o", path("o.obj"), "--strict"}), 2);
    EXPECT_FALSE(fs::exists(path("o.obj")));
    EXPECT_EQ(run({"render", path("bowtie.obj"), "-o", path("o.png"), "--strict"}), 2);
    EXPECT_EQ(run({"edit", path("bowtie.obj"), "--screenshot", path("o.png"), "--strict"}), 2);
    EXPECT_FALSE(fs::exists(path("o.png")));
    ASSERT_EQ(run({"refine", path("bowtie.obj"), "-o", path("o.obj"), "--level", "1"}), 0);
    // The split vertex stays split in the saved file: two separate triangles of 6 vertices each.
    const LoadedMesh saved = read_obj_file(path("o.obj"));
    EXPECT_EQ(saved.triangles.size(), 8u);
    EXPECT_EQ(saved.positions.size(), 12u);
    EXPECT_TRUE(saved.warnings.empty());
}

TEST_F(CliCommands, InfoListsWhatRidesOnTheMesh) {
    write("textured.obj", "mtllib none.mtl\nv 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\n"
                          "g a\nusemtl m\nf 1/1 2/2 3/3\n");
    ::testing::internal::CaptureStdout();
    ASSERT_EQ(run({"info", path("textured.obj")}), 0);
    const std::string out = ::testing::internal::GetCapturedStdout();
    EXPECT_NE(out.find("texture coordinates: 3 (per corner)\nvertex colours: yes\nmaterials: 1 used, 0 defined in the material "
                       "libraries\ngroups: 1\n"),
              std::string::npos)
        << out;
}

// --plain leaves out the #rgb lines: the file loads as a plain mesh of the same triangles.
TEST_F(CliCommands, PlainOutputHasNoStateLines) {
    write("script.txt", "level 2\n");
    ASSERT_EQ(run({"refine", path("octahedron.obj"), "-o", path("plain.obj"), "--level", "2", "--plain"}), 0);
    ASSERT_EQ(run({"apply", path("octahedron.obj"), path("script.txt"), "-o", path("applied.obj"), "--plain"}), 0);
    ASSERT_EQ(run({"refine", path("octahedron.obj"), "-o", path("full.obj"), "--level", "2"}), 0);
    for (const char* name : {"plain.obj", "applied.obj"}) {
        const std::string text = read_text_file(path(name));
        EXPECT_EQ(text.find("#rgb"), std::string::npos) << name;
        const LoadedMesh plain = read_obj_file(path(name));
        EXPECT_FALSE(plain.adaptive) << name;
        EXPECT_EQ(plain.triangles.size(), 8u * 16u) << name;
        EXPECT_EQ(triangles_by_position(plain), triangles_by_position(read_obj_file(path("full.obj")))) << name;
    }
}

TEST_F(CliCommands, RefineThenLevelZeroGivesBackTheInput) {
    ASSERT_EQ(run({"refine", path("octahedron.obj"), "-o", path("fine.obj"), "--level", "3", "--sphere", "1,0,0,0.8"}), 0);
    const LoadedMesh fine = read_obj_file(path("fine.obj"));
    ASSERT_TRUE(fine.adaptive);
    EXPECT_GT(fine.triangles.size(), 8u);
    ASSERT_EQ(run({"refine", path("fine.obj"), "-o", path("base.obj"), "--level", "0"}), 0);
    const LoadedMesh input = read_obj_file(path("octahedron.obj"));
    const LoadedMesh base = read_obj_file(path("base.obj"));
    EXPECT_EQ(base.positions, input.positions);
    EXPECT_EQ(triangles_by_position(base), triangles_by_position(input));
}

TEST_F(CliCommands, ApplyRunsTheScriptLikeRefine) {
    write("script.txt", "# comment\nlevel 2\n\nlevel 4 sphere 1 0 0 0.5\n");
    ASSERT_EQ(run({"apply", path("octahedron.obj"), path("script.txt"), "-o", path("applied.obj")}), 0);
    ASSERT_EQ(run({"refine", path("octahedron.obj"), "-o", path("step.obj"), "--level", "2"}), 0);
    ASSERT_EQ(run({"refine", path("step.obj"), "-o", path("refined.obj"), "--level", "4", "--sphere", "1,0,0,0.5"}), 0);
    const LoadedMesh applied = read_obj_file(path("applied.obj"));
    const LoadedMesh refined = read_obj_file(path("refined.obj"));
    EXPECT_EQ(triangles_by_position(applied), triangles_by_position(refined));
}

// Every operation on a closed mesh changes the triangle count by exactly two, and the driver refines
// until the count reaches the budget and trims back down to it, so an even budget is met exactly.
TEST_F(CliCommands, ApplyBudgetMeetsTheTriangleCountExactly) {
    write("script.txt", "budget 500\n");
    ASSERT_EQ(run({"apply", path("octahedron.obj"), path("script.txt"), "-o", path("budget.obj")}), 0);
    const LoadedMesh fine = read_obj_file(path("budget.obj"));
    ASSERT_TRUE(fine.adaptive);
    EXPECT_EQ(fine.triangles.size(), 500u);
    write("down.txt", "level 4\nbudget 100\n");
    ASSERT_EQ(run({"apply", path("octahedron.obj"), path("down.txt"), "-o", path("down.obj")}), 0);
    EXPECT_EQ(read_obj_file(path("down.obj")).triangles.size(), 100u);
    write("bad.txt", "budget lots\n");
    EXPECT_EQ(run({"apply", path("octahedron.obj"), path("bad.txt"), "-o", path("bad.obj")}), 2);
}

// Running out of memory is reported (exit 3, nothing saved), not an abort: the child process gets
// 256 MB of address space beyond what it uses and asks for level 12 (134M triangles).
TEST_F(CliCommands, OutOfMemoryIsExitThreeNotAnAbort) {
    const int status = test::wait_status_of_child([&] {
        long pages = 0;
        std::ifstream("/proc/self/statm") >> pages;
        const rlim_t limit = static_cast<rlim_t>(pages) * static_cast<rlim_t>(::sysconf(_SC_PAGESIZE)) + (rlim_t{256} << 20);
        const rlimit address_space{limit, limit};
        ::setrlimit(RLIMIT_AS, &address_space);
        return run({"refine", path("octahedron.obj"), "-o", path("fine.obj"), "--level", "12"});
    });
    ASSERT_TRUE(WIFEXITED(status)) << "the command died of signal " << WTERMSIG(status);
    EXPECT_EQ(WEXITSTATUS(status), 3);
    EXPECT_EQ(std::distance(fs::directory_iterator(folder_), fs::directory_iterator()), 1) << "only the input is there";
}

}  // namespace
}  // namespace rgbio
