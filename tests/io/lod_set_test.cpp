// The pieces of a set of levels of detail (io/script/lod_set.h): the requests a list asks for, finest
// first; each level the canonical mesh of its request whatever the input holds; the switch coverage
// derived from the errors by its formula; nesting by position; the per-level file names.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "io/script/lod_set.h"
#include "io/script/triangle_limit.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/loop_geometry.h"
#include "support/test_meshes.h"

namespace {

std::vector<glm::dvec3> limit_positions(const rgb::Mesh& mesh) {
    std::vector<glm::dvec3> out;
    for (rgb::VertexId v : mesh.vertices()) out.push_back(rgb::limit_position_uncached(mesh, v));
    return out;
}

TEST(LodSet, RequestsComeFinestFirst) {
    const rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::octahedron());
    std::vector<rgbio::ScriptLine> levels = rgbio::lod_set_requests(rgbio::LodSetCriterion::Levels, "1,3,2", mesh);
    ASSERT_EQ(levels.size(), 3u);
    EXPECT_EQ(levels[0].text, "3");
    EXPECT_EQ(std::get<rgb::LevelRequest>(levels[2].edit).level, 1);
    const auto budgets = rgbio::lod_set_requests(rgbio::LodSetCriterion::Budgets, "100,5000,700", mesh);
    EXPECT_EQ(std::get<rgbio::BudgetEdit>(budgets[0].edit).triangles, 5000u);
    EXPECT_EQ(std::get<rgbio::BudgetEdit>(budgets[2].edit).triangles, 100u);
    // 1% of the diagonal is larger than 0.001 on a mesh about 2.8 across.
    const auto tolerances = rgbio::lod_set_requests(rgbio::LodSetCriterion::Tolerances, "1%,0.001", mesh);
    EXPECT_EQ(tolerances[0].text, "0.001");
    EXPECT_EQ(tolerances[1].text, "1%");
    for (const auto& [criterion, list] : {std::pair{rgbio::LodSetCriterion::Levels, "1,,2"}, std::pair{rgbio::LodSetCriterion::Levels, "21"},
                                          std::pair{rgbio::LodSetCriterion::Levels, "2,2"}, std::pair{rgbio::LodSetCriterion::Levels, "-1"},
                                          std::pair{rgbio::LodSetCriterion::Budgets, "0"}, std::pair{rgbio::LodSetCriterion::Budgets, "1.5"},
                                          std::pair{rgbio::LodSetCriterion::Tolerances, "0"}, std::pair{rgbio::LodSetCriterion::Tolerances, ""}})
        EXPECT_THROW(rgbio::lod_set_requests(criterion, list, mesh), std::invalid_argument) << list;
}

TEST(LodSet, LevelsAreCanonicalAndNest) {
    const rgb::Mesh base = rgbtest::make_rgb_mesh(rgbtest::icosahedron());
    // The input already holds detail: each level is still the mesh of its request alone.
    rgb::Mesh painted = base;
    rgb::LevelRequest request;
    request.level = 3;
    request.sphere = rgb::Sphere{{1, 0, 0}, 0.7};
    rgb::apply_request(painted, request);
    for (const auto& [criterion, list] : {std::pair{rgbio::LodSetCriterion::Levels, "3,2,1"}, std::pair{rgbio::LodSetCriterion::Budgets, "400,120"}}) {
        const auto requests = rgbio::lod_set_requests(criterion, list, base);
        std::vector<glm::dvec3> finer;
        for (std::size_t i = 0; i < requests.size(); ++i) {
            const rgb::Mesh from_base = rgbio::lod_set_level(base, requests[i], 1'000'000);
            const rgb::Mesh from_painted = rgbio::lod_set_level(painted, requests[i], 1'000'000);
            const std::vector<glm::dvec3> positions = limit_positions(from_base);
            EXPECT_EQ(from_base.num_faces(), from_painted.num_faces()) << list << " LOD" << i;
            EXPECT_TRUE(rgbio::positions_nested(limit_positions(from_painted), positions)) << list << " LOD" << i;
            if (i > 0) {
                EXPECT_TRUE(rgbio::positions_nested(positions, finer)) << list << " LOD" << i;
                EXPECT_FALSE(rgbio::positions_nested(finer, positions)) << list << " LOD" << i;
            }
            finer = positions;
        }
    }
    EXPECT_THROW(rgbio::lod_set_level(base, rgbio::lod_set_requests(rgbio::LodSetCriterion::Levels, "4", base)[0], 100),
                 rgbio::TooLarge);
}

TEST(LodSet, SwitchCoverageFollowsItsFormula) {
    // Size 2160, errors 1, 4, 8: level 0 down to ((2160 / 4) / 1080)^2 = 1/4, level 1 down to
    // ((2160 / 8) / 1080)^2 = 1/16, the coarsest to 0.
    const std::vector<double> coverage = rgbio::switch_coverage({1.0, 4.0, 8.0}, 2160.0);
    ASSERT_EQ(coverage.size(), 3u);
    EXPECT_DOUBLE_EQ(coverage[0], 0.25);
    EXPECT_DOUBLE_EQ(coverage[1], 0.0625);
    EXPECT_EQ(coverage[2], 0.0);
    // At most 1, never increasing, a level without error kept down to 1.
    const std::vector<double> exact = rgbio::switch_coverage({0.0, 0.0, 1.0}, 1.0);
    ASSERT_EQ(exact.size(), 3u);
    EXPECT_EQ(exact[0], 1.0);
    EXPECT_DOUBLE_EQ(exact[1], 1.0 / (1080.0 * 1080.0));
    EXPECT_EQ(exact[2], 0.0);
    EXPECT_EQ(rgbio::switch_coverage({1.0, 8.0, 4.0}, 2160.0), (std::vector<double>{0.0625, 0.0625, 0.0}));
    EXPECT_EQ(rgbio::switch_coverage({1.0}, 1.0), (std::vector<double>{0.0}));
}

TEST(LodSet, FileNames) {
    EXPECT_EQ(rgbio::lod_file_name("lv.obj", 0), "lv_LOD0.obj");
    EXPECT_EQ(rgbio::lod_file_name("out/set.v2.PLY", 3), "out/set.v2_LOD3.PLY");
    EXPECT_EQ(rgbio::lod_file_name("/a/b/mesh", 1), "/a/b/mesh_LOD1");
}

}  // namespace
