// `rgbsub info`: the whole report, line for line, for meshes whose counts are known by hand.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "cli/dispatch.h"
#include "command_test_support.h"
#include "io/mesh_file.h"
#include "obj_test_support.h"
#include "rgb/mesh/detail_positions.h"
#include "rgb/mesh/mesh.h"

namespace cli {
namespace {

class InfoCommand : public test::CommandFolder {
protected:
    // The report for `text`, which must be accepted.
    std::string info(const std::string& name, const std::string& text) {
        const test::CommandRun run = test::run_command({"info", write(name, text)});
        EXPECT_EQ(run.exit_code, 0) << run.err;
        EXPECT_EQ(run.err, "");
        return run.out;
    }
};

// The header of the quality lines (rgb/values/triangle_quality.h).
const std::string kQuality = "triangle quality per level (angles in degrees; aspect ratio: longest edge x perimeter / (4 sqrt(3) x area), 1 when equilateral):\n";

// Closed and genus 0: V - E + F = 2, E = 3F/2. Every face equilateral: angles of 60 degrees, aspect ratio 1.
TEST_F(InfoCommand, ClosedOctahedron) {
    EXPECT_EQ(info("octahedron.obj", rgbio::test::kOctahedron),
              path("octahedron.obj") + ": valid\n"
              "adaptive state: none (base mesh)\n"
              "vertices: 6\nedges: 12\nfaces: 8\nboundary loops: 0\nEuler characteristic: 2\n"
              "triangles per colour: green 8, red 0, blue 0\n"
              "triangles per level: 0:8\n" + kQuality +
              "  level 0: minimum angle 60, mean minimum angle 60, worst aspect ratio 1\n");
}

// A square ring: four outer and four inner corners, two triangles per side, two boundary loops. Each
// side's triangles, (-2,-2) (2,-2) (1,-1) and (-2,-2) (1,-1) (-1,-1) and their turns, have the smallest
// angle atan(1/3) = 18.4349 degrees; the worst aspect ratio is the first's: edges 4, sqrt 2, sqrt 10,
// area 2: 4 (4 + sqrt 2 + sqrt 10) / (8 sqrt 3) = 3.00174.
TEST_F(InfoCommand, AnnulusHasTwoBoundaryLoops) {
    const std::string ring =
        "v -2 -2 0\nv 2 -2 0\nv 2 2 0\nv -2 2 0\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
        "f 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";
    EXPECT_EQ(info("ring.obj", ring),
              path("ring.obj") + ": valid\n"
              "adaptive state: none (base mesh)\n"
              "vertices: 8\nedges: 16\nfaces: 8\nboundary loops: 2\nEuler characteristic: 0\n"
              "triangles per colour: green 8, red 0, blue 0\n"
              "triangles per level: 0:8\n" + kQuality +
              "  level 0: minimum angle 18.4349, mean minimum angle 18.4349, worst aspect ratio 3.00174\n");
}

// A fixed file says so and lists what was fixed: a quad split in two, an unused vertex dropped.
TEST_F(InfoCommand, FixesAreListedAsWarnings) {
    const test::CommandRun run = test::run_command(
        {"info", write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 5 5 5\nf 1 2 3 4\n")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const std::string head = path("quad.obj") + ": valid after fixes\n";
    EXPECT_EQ(run.out.substr(0, head.size()), head);
    std::size_t warnings = 0;
    for (std::size_t at = run.out.find("\nwarning: "); at != std::string::npos; at = run.out.find("\nwarning: ", at + 1)) ++warnings;
    EXPECT_EQ(warnings, 2u) << run.out;
    EXPECT_NE(run.out.find("vertices: 4\nedges: 5\nfaces: 2\nboundary loops: 1\nEuler characteristic: 1\n"), std::string::npos)
        << run.out;
}

// Texture coordinates at some corners of a face only are dropped by every command: info says so as
// refine does, with the same warning (issue 30, low items). Before, info listed "texture coordinates:
// 3 (per corner)" without a warning while refine dropped them.
TEST_F(InfoCommand, PartialTextureCoordinatesAreReportedAsRefineDropsThem) {
    const std::string file = write("partial.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\nf 3 2/2 4\n");
    const std::string dropped = "texture coordinates dropped: some faces have them at some corners only (f v/vt v v/vt), and "
                                "subdividing them needs one at every corner of a textured face";
    const test::CommandRun info = test::run_command({"info", file});
    ASSERT_EQ(info.exit_code, 0) << info.err;
    const std::string head = file + ": valid after fixes\nwarning: " + dropped +
                             "\nadaptive state: none (base mesh)\ntexture coordinates: 3 in the file, dropped (see the warnings)\n";
    EXPECT_EQ(info.out.substr(0, head.size()), head) << info.out;
    const test::CommandRun refine = test::run_command({"refine", file, "-o", path("out.obj"), "--level", "1"});
    ASSERT_EQ(refine.exit_code, 0) << refine.err;
    EXPECT_NE(refine.err.find(file + ": warning: " + dropped), std::string::npos) << refine.err;
}

// A saved level-1 refinement: 4 * 8 green faces of level 1; V = 6 + 12 edge points, E = 3F/2. By Loop's
// rules the corners move to 132/256 of themselves (valence 4: beta = 31/256, the neighbours sum to 0)
// and the edge points are 3/8 (a + b) (the opposite vertices sum to 0): 8 equilateral middle triangles
// and 24 isosceles corner ones, whose smallest angle is 48.5409 degrees, the mean of the 32 smallest
// angles 51.4057, the worst aspect ratio 1.28045 (computed from those points by the law of cosines
// and Heron's formula).
TEST_F(InfoCommand, SavedStateIsReportedWithItsLevels) {
    ASSERT_EQ(test::run_command({"refine", write("octahedron.obj", rgbio::test::kOctahedron), "-o", path("fine.obj"), "--level", "1"})
                  .exit_code,
              0);
    const test::CommandRun run = test::run_command({"info", path("fine.obj")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out, path("fine.obj") + ": valid\n"
                       "adaptive state: restored from the file's #rgb lines\n"
                       "vertices: 18\nedges: 48\nfaces: 32\nboundary loops: 0\nEuler characteristic: 2\n"
                       "triangles per colour: green 32, red 0, blue 0\n"
                       "triangles per level: 1:32\n" + kQuality +
                       "  level 1: minimum angle 48.5409, mean minimum angle 51.4057, worst aspect ratio 1.28045\n");
}

// A cage with detail of levels per face: the octahedron, its faces at levels 1 3 2 2 1 3 2 1. The
// points counted by hand: 6 base vertices; on the 12 edges 2^K_e - 1 each for K_e, the finer level of
// the edge's two faces (1, 3, 2, 3, 3, 2, 2, 2, 1, 3, 3, 2: 52); inside the faces 0, 3 or 21 for
// levels 1, 2, 3 (51): 109.
TEST_F(InfoCommand, DetailIsReportedWithItsLevels) {
    const std::vector<glm::dvec3> positions{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const std::vector<rgb::Triangle> triangles{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    const rgb::BaseMesh plain(positions, triangles);
    const std::vector<std::uint8_t> levels{1, 3, 2, 2, 1, 3, 2, 1};
    std::vector<glm::dvec3> values;
    for (const rgb::SurfacePoint& p : rgb::DetailPositions::grid_points(plain, levels))
        values.push_back(rgb::base_space_position(plain, p));
    auto detail = std::make_shared<const rgb::DetailPositions>(plain, levels, values, rgb::DetailOrigin{"scan.obj", 12345, 7});
    const rgb::Mesh mesh(std::make_shared<const rgb::BaseMesh>(positions, triangles, rgb::SharpFeatures{}, detail));
    const std::string out = info("cage.obj", rgbio::format_obj(mesh, {}));
    // 83 points, counted by hand: 6 vertices; inside the faces (2^K - 1)(2^K - 2) / 2 = 0, 21, 3, 3, 0,
    // 21, 3, 0; on the 12 edges 2^K_e - 1 with K_e the coarser face's level: 7 on 1-2 (3 and 3), 3 each
    // on 1-4, 1-3, 3-4, 1-5 (level 2), 1 each on the other seven (level 1).
    EXPECT_NE(out.find("detail: from scan.obj (12345 triangles), stored to levels 1..3 (each base face its own, each base edge its "
                       "coarser face's), 83 points; finer levels interpolate them linearly (inside a face its grid triangle, on a "
                       "base edge its two samples)\n"
                       "detail points on the nearest point of the surface (no ray hit along the limit normal): 7\n"),
              std::string::npos)
        << out;
}

// info saves nothing, so running out of memory in it says nothing about saving (issue 30, low items);
// the commands that save still say that nothing was saved.
TEST(InfoOutOfMemory, SaysNothingAboutSaving) {
    const std::length_error too_long("vector::reserve");
    EXPECT_EQ(out_of_memory_message("info", nullptr), "out of memory: the request needs more memory than the system would give");
    EXPECT_EQ(out_of_memory_message("info", &too_long), "out of memory: a size beyond what this machine can hold (vector::reserve)");
    for (const char* command : {"refine", "apply", "lods", "remesh", "render"}) {
        EXPECT_TRUE(out_of_memory_message(command, nullptr).ends_with("system would give; nothing was saved")) << command;
        EXPECT_TRUE(out_of_memory_message(command, &too_long).ends_with("(vector::reserve); nothing was saved")) << command;
    }
}

}  // namespace
}  // namespace cli
