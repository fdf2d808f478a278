// `rgbsub refine` on the octahedron, checked against uniform Loop subdivision worked out by hand.
//
// Every octahedron vertex has valence 4, so Loop's weight is beta(4) = (5/8 - (3/8)^2) / 4 = 31/256;
// vertices inserted later have valence 6, beta(6) = (5/8 - (1/2)^2) / 6 = 1/16. By the octahedral
// symmetry each level's vertices fall into classes given by one point and its signed permutations.
// Level 1: the corners move to 1 - 4 * 31/256 = 33/64 (their neighbours cancel), edge points to
// 3/8 (a + b) = (3/8, 3/8, 0). Level 2 (the same rules once more):
//   corners                  (1833/4096, 0, 0)          6
//   old edge points          (321/1024, 321/1024, 0)    12
//   corner-to-edge midpoints (219/512, 9/64, 0)         24
//   edge-to-edge midpoints   (177/512, 3/16, 3/16)      24
// and Loop's limit rule p + chi * sum (q - p) with chi = 1 / (3 / (8 beta) + n) sends them to
//   (24/55, 0, 0), (75/256, 75/256, 0), (6655/16384, 523/4096, 0), (671/2048, 721/4096, 721/4096).
#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <sstream>

#include <glm/geometric.hpp>

#include "command_test_support.h"
#include "io/obj_reader.h"
#include "obj_test_support.h"

namespace cli {
namespace {

using Point = std::array<double, 3>;
using rgbio::test::kOctahedron;
using rgbio::test::triangles_by_position;

// `p` with its coordinates permuted and their signs flipped in every way.
std::set<Point> signed_permutations(Point p) {
    std::set<Point> out;
    std::sort(p.begin(), p.end());
    do {
        for (int signs = 0; signs < 8; ++signs)
            out.insert({signs & 1 ? -p[0] : p[0], signs & 2 ? -p[1] : p[1], signs & 4 ? -p[2] : p[2]});
    } while (std::next_permutation(p.begin(), p.end()));
    return out;
}

// The union of the classes; the counts confirm that no two classes share a point.
std::multiset<Point> octahedron_classes(const std::vector<Point>& representatives) {
    std::multiset<Point> all;
    for (const Point& p : representatives)
        for (const Point& q : signed_permutations(p)) all.insert(q);
    return all;
}

std::multiset<Point> level_two_positions() {
    return octahedron_classes({{1833.0 / 4096, 0, 0}, {321.0 / 1024, 321.0 / 1024, 0}, {219.0 / 512, 9.0 / 64, 0},
                               {177.0 / 512, 3.0 / 16, 3.0 / 16}});
}

std::multiset<Point> level_two_limits() {
    return octahedron_classes({{24.0 / 55, 0, 0}, {75.0 / 256, 75.0 / 256, 0}, {6655.0 / 16384, 523.0 / 4096, 0},
                               {671.0 / 2048, 721.0 / 4096, 721.0 / 4096}});
}

std::multiset<Point> positions_of(const rgbio::LoadedMesh& mesh) {
    std::multiset<Point> out;
    for (const glm::dvec3& p : mesh.positions) out.insert({p.x, p.y, p.z});
    return out;
}

// Each expected point matched by a distinct written one within `tolerance` per coordinate (the file
// holds the shortest decimals that read back as the computed doubles).
void expect_same_points(const std::multiset<Point>& got, const std::multiset<Point>& want, double tolerance) {
    ASSERT_EQ(got.size(), want.size());
    std::vector<Point> unmatched(got.begin(), got.end());
    for (const Point& w : want) {
        const auto near = std::find_if(unmatched.begin(), unmatched.end(), [&](const Point& g) {
            return std::abs(g[0] - w[0]) <= tolerance && std::abs(g[1] - w[1]) <= tolerance && std::abs(g[2] - w[2]) <= tolerance;
        });
        ASSERT_NE(near, unmatched.end()) << "no vertex at (" << w[0] << ", " << w[1] << ", " << w[2] << ")";
        unmatched.erase(near);
    }
}

class RefineCommand : public test::CommandFolder {
protected:
    void SetUp() override {
        CommandFolder::SetUp();
        input_ = write("octahedron.obj", kOctahedron);
    }
    std::string input_;
};

TEST_F(RefineCommand, ClassesOfTheHandComputedLevelsAreDisjoint) {
    const std::multiset<Point> positions = level_two_positions(), limits = level_two_limits();
    EXPECT_EQ(positions.size(), 6u + 12u + 24u + 24u);
    EXPECT_EQ(std::set<Point>(positions.begin(), positions.end()).size(), 66u);
    EXPECT_EQ(std::set<Point>(limits.begin(), limits.end()).size(), 66u);
}

TEST_F(RefineCommand, LevelTwoEverywhereIsUniformLoopSubdivision) {
    ASSERT_EQ(test::run_command({"refine", input_, "-o", path("fine.obj"), "--level", "2"}).exit_code, 0);
    const rgbio::LoadedMesh fine = rgbio::read_obj_file(path("fine.obj"));
    ASSERT_TRUE(fine.adaptive);
    EXPECT_EQ(fine.triangles.size(), 8u * 4u * 4u);  // each level splits every triangle in four
    // The weights come from cos(2 pi / n), whose rounding may move a coordinate by an ulp or two.
    expect_same_points(positions_of(fine), level_two_positions(), 1e-15);
}

TEST_F(RefineCommand, RefineThenLevelZeroGivesBackTheInput) {
    const rgbio::LoadedMesh input = rgbio::read_obj_file(input_);
    for (const std::vector<std::string>& where : {std::vector<std::string>{}, std::vector<std::string>{"--sphere", "1,0,0,0.8"}}) {
        std::vector<std::string> refine{"refine", input_, "-o", path("fine.obj"), "--level", "3"};
        refine.insert(refine.end(), where.begin(), where.end());
        ASSERT_EQ(test::run_command(refine).exit_code, 0);
        const rgbio::LoadedMesh fine = rgbio::read_obj_file(path("fine.obj"));
        if (where.empty()) EXPECT_EQ(fine.triangles.size(), 8u * 64u);
        else EXPECT_GT(fine.triangles.size(), 8u) << "the sphere around a corner refines its faces";
        ASSERT_EQ(test::run_command({"refine", path("fine.obj"), "-o", path("base.obj"), "--level", "0"}).exit_code, 0);
        const rgbio::LoadedMesh base = rgbio::read_obj_file(path("base.obj"));
        EXPECT_EQ(base.positions, input.positions);
        EXPECT_EQ(triangles_by_position(base), triangles_by_position(input));
    }
}

TEST_F(RefineCommand, LimitPositionsAreLoopsLimitOfEveryVertex) {
    const test::CommandRun run =
        test::run_command({"refine", input_, "-o", path("limit.obj"), "--level", "2", "--positions", "limit"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "") << "every vertex of a uniform level has its ring, so no fallback is reported";
    const rgbio::LoadedMesh limit = rgbio::read_obj_file(path("limit.obj"));
    expect_same_points(positions_of(limit), level_two_limits(), 1e-15);
    EXPECT_NE(read("limit.obj").find("positions: limit"), std::string::npos);
}

// Level 1 of the octahedron is symmetric under each coordinate reflection and under swapping the two
// axes an edge point lies between, so every vertex normal points straight away from the centre.
TEST_F(RefineCommand, NormalsAreWrittenPerVertexAndReferencedByTheFaces) {
    ASSERT_EQ(test::run_command({"refine", input_, "-o", path("normals.obj"), "--level", "1", "--normals"}).exit_code, 0);
    std::istringstream lines(read("normals.obj"));
    std::vector<glm::dvec3> positions, normals;
    std::size_t faces = 0;
    for (std::string line; std::getline(lines, line);) {
        std::istringstream words(line);
        std::string kind;
        words >> kind;
        glm::dvec3 v;
        if (kind == "v" && words >> v.x >> v.y >> v.z) positions.push_back(v);
        if (kind == "vn" && words >> v.x >> v.y >> v.z) normals.push_back(v);
        if (kind != "f") continue;
        ++faces;
        for (std::string corner; words >> corner;) {
            const std::size_t slashes = corner.find("//");
            ASSERT_NE(slashes, std::string::npos) << line;
            EXPECT_EQ(corner.substr(0, slashes), corner.substr(slashes + 2)) << "each corner uses its vertex's normal";
        }
    }
    EXPECT_EQ(faces, 32u);
    ASSERT_EQ(positions.size(), 18u);
    ASSERT_EQ(normals.size(), positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const glm::dvec3 want = glm::normalize(positions[i]);
        EXPECT_NEAR(glm::distance(normals[i], want), 0.0, 1e-15) << "vertex " << i + 1;
    }
}

}  // namespace
}  // namespace cli
