// The info/refine/apply subcommands through the dispatcher: exit codes 0/1/2/3 and apply's scripts
// (refine itself: tests/cli/refine_command_test.cpp).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <tuple>

#include <sys/resource.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "cli/dispatch.h"
#include "io/obj_reader.h"
#include "obj_test_support.h"
#include "rgb/mesh/mesh.h"
#include "scratch_folder.h"
#include "support/request_oracle.h"
#include "support/uniform_loop_oracle.h"

namespace rgbio {
namespace {

namespace fs = std::filesystem;
using test::triangles_by_position;

class CliCommands : public test::ScratchFolder {
protected:
    void SetUp() override {
        ScratchFolder::SetUp();
        write("octahedron.obj", test::kOctahedron);
    }
    static int run(std::vector<std::string> args) { return cli::dispatch(args); }
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

using PositionTriangle = std::array<std::array<double, 3>, 3>;

// Each triangle's corner UVs keyed by its corners' positions (rotated to start at the smallest).
std::map<PositionTriangle, std::array<glm::dvec2, 3>> uvs_by_position(const LoadedMesh& mesh) {
    std::map<PositionTriangle, std::array<glm::dvec2, 3>> uvs;
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        PositionTriangle p;
        std::array<glm::dvec2, 3> uv;
        for (std::size_t i = 0; i < 3; ++i) {
            const glm::dvec3& q = mesh.positions[mesh.triangles[f][i]];
            p[i] = {q.x, q.y, q.z};
            uv[i] = mesh.texcoords[mesh.triangle_texcoords[f][i]];
        }
        const auto first = std::min_element(p.begin(), p.end()) - p.begin();
        std::rotate(p.begin(), p.begin() + first, p.end());
        std::rotate(uv.begin(), uv.begin() + first, uv.end());
        uvs.emplace(p, uv);
    }
    return uvs;
}

TEST_F(CliCommands, RefineWritesExactUvsAndLevelZeroGivesBackTheInputUvs) {
    // The octahedron's upper and lower halves as two UV islands (a seam along the equator).
    write("textured.obj", "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
                          "vt 0.1 0.2\nvt 0.3 0.2\nvt 0.2 0.1\nvt 0.2 0.3\nvt 0.2 0.2\n"
                          "vt 0.7 0.2\nvt 0.9 0.2\nvt 0.8 0.1\nvt 0.8 0.3\nvt 0.8 0.2\n"
                          "f 1/1 3/3 5/5\nf 3/3 2/2 5/5\nf 2/2 4/4 5/5\nf 4/4 1/1 5/5\n"
                          "f 3/8 1/6 6/10\nf 2/7 3/8 6/10\nf 4/9 2/7 6/10\nf 1/6 4/9 6/10\n");
    ASSERT_EQ(run({"refine", path("textured.obj"), "-o", path("fine.obj"), "--level", "3", "--sphere", "1,0,0,0.8",
                   "--uv-interpolation", "boundaries"}),
              0);
    const std::string text = read_text_file(path("fine.obj"));
    EXPECT_NE(text.find("\n#rgb uv-interpolation boundaries\n"), std::string::npos);
    const LoadedMesh fine = read_obj_file(path("fine.obj"));
    ASSERT_TRUE(fine.adaptive);
    ASSERT_EQ(fine.triangle_texcoords.size(), fine.triangles.size());
    // With `boundaries` the seam's UVs stay on the base UV segments: the midpoint of the equator edge
    // from (1,0,0) to (0,1,0) on the upper island is halfway between vt 1 and vt 3.
    const glm::dvec2 midpoint = 0.5 * (glm::dvec2(0.1, 0.2) + glm::dvec2(0.2, 0.1));
    bool found = false;
    for (std::size_t f = 0; f < fine.triangles.size(); ++f)
        for (std::size_t i = 0; i < 3; ++i)
            if (std::abs(fine.positions[fine.triangles[f][i]].z) < 1e-12 && fine.texcoords[fine.triangle_texcoords[f][i]] == midpoint)
                found = true;
    EXPECT_TRUE(found);
    EXPECT_EQ(run({"refine", path("textured.obj"), "-o", path("bad.obj"), "--level", "1", "--uv-interpolation", "smooth"}), 1);

    ASSERT_EQ(run({"refine", path("fine.obj"), "-o", path("base.obj"), "--level", "0"}), 0);
    EXPECT_EQ(uvs_by_position(read_obj_file(path("base.obj"))), uvs_by_position(read_obj_file(path("textured.obj"))));
}

// Base-space positions of a saved adaptive mesh's vertices (where each sits under midpoint
// subdivision of the base), sorted.
std::vector<glm::dvec3> base_space_vertices(const LoadedMesh& mesh) {
    std::vector<glm::dvec3> out;
    for (rgb::VertexId v : mesh.adaptive->vertices()) out.push_back(mesh.adaptive->base_space_position(v));
    std::sort(out.begin(), out.end(), [](const glm::dvec3& a, const glm::dvec3& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); });
    return out;
}

testing::AssertionResult same_points(std::vector<glm::dvec3> a, std::vector<glm::dvec3> b) {
    auto less = [](const glm::dvec3& p, const glm::dvec3& q) { return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z); };
    std::sort(a.begin(), a.end(), less);
    std::sort(b.begin(), b.end(), less);
    if (a.size() != b.size()) return testing::AssertionFailure() << a.size() << " vs " << b.size() << " vertices";
    for (std::size_t i = 0; i < a.size(); ++i)
        if (glm::distance(a[i], b[i]) > 1e-12) return testing::AssertionFailure() << "vertex " << i << " differs";
    return testing::AssertionSuccess();
}

// The script's vertex set is the one the meaning of its requests gives (computed by the independent
// request model on the uniform Loop oracle), and refine one request at a time gives the same file.
TEST_F(CliCommands, ApplyRunsTheScriptByItsMeaning) {
    write("script.txt", "# comment\nlevel 2\n\nlevel 4 sphere 1 0 0 0.5\n");
    ASSERT_EQ(run({"apply", path("octahedron.obj"), path("script.txt"), "-o", path("applied.obj")}), 0);
    const LoadedMesh input = read_obj_file(path("octahedron.obj"));
    const rgbtest::UniformLoopOracle oracle(input.positions, input.triangles, 4);
    const rgbtest::RequestOracle meaning(oracle);
    std::set<rgbtest::Identity> expected = meaning.base();
    expected = meaning.refined(expected, 2, {glm::dvec3(0.0), 1e9});
    expected = meaning.refined(expected, 4, {glm::dvec3(1, 0, 0), 0.5});
    std::vector<glm::dvec3> expected_points;
    for (rgbtest::Identity id : expected) expected_points.push_back(meaning.base_space(id));
    const LoadedMesh applied = read_obj_file(path("applied.obj"));
    ASSERT_TRUE(applied.adaptive);
    EXPECT_TRUE(same_points(base_space_vertices(applied), expected_points));
    ASSERT_EQ(run({"refine", path("octahedron.obj"), "-o", path("step.obj"), "--level", "2"}), 0);
    ASSERT_EQ(run({"refine", path("step.obj"), "-o", path("refined.obj"), "--level", "4", "--sphere", "1,0,0,0.5"}), 0);
    EXPECT_EQ(triangles_by_position(applied), triangles_by_position(read_obj_file(path("refined.obj"))));
}

// A budget means the largest mesh of the driver's canonical order within it: never more triangles,
// the same mesh whatever the file held before, and a smaller budget's vertices are among a larger's.
TEST_F(CliCommands, ApplyBudgetStaysWithinAndIgnoresWhatCameBefore) {
    write("small.txt", "budget 100\n");
    write("large.txt", "budget 500\n");
    write("after.txt", "level 4\nlevel 1 sphere 1 0 0 0.3\nbudget 500\n");
    ASSERT_EQ(run({"apply", path("octahedron.obj"), path("small.txt"), "-o", path("small.obj")}), 0);
    ASSERT_EQ(run({"apply", path("octahedron.obj"), path("large.txt"), "-o", path("large.obj")}), 0);
    ASSERT_EQ(run({"apply", path("octahedron.obj"), path("after.txt"), "-o", path("after.obj")}), 0);
    const LoadedMesh small = read_obj_file(path("small.obj")), large = read_obj_file(path("large.obj"));
    ASSERT_TRUE(small.adaptive && large.adaptive);
    EXPECT_LE(small.triangles.size(), 100u);
    EXPECT_LE(large.triangles.size(), 500u);
    EXPECT_GE(large.triangles.size(), 450u);  // a step adds a handful of triangles, not dozens
    EXPECT_EQ(triangles_by_position(large), triangles_by_position(read_obj_file(path("after.obj"))));
    const std::vector<glm::dvec3> few = base_space_vertices(small), many = base_space_vertices(large);
    auto less = [](const glm::dvec3& p, const glm::dvec3& q) { return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z); };
    EXPECT_TRUE(std::includes(many.begin(), many.end(), few.begin(), few.end(), less));
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
