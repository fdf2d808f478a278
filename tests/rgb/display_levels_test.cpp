// rgb::display_levels (one pass over the faces, for saving) against rgb::display_level (a walk
// around each vertex, a second implementation), and the displayed positions they give against the
// hierarchy evaluator, which never looks at the mesh: on the meshes a budget run leaves after every
// few steps, every vertex bit for bit; dead slots (freed by the run's removals) read 0.
#include <cstddef>

#include <gtest/gtest.h>

#include "rgb/lod/lod_driver.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/hierarchy_evaluator.h"
#include "rgb/values/loop_geometry.h"
#include "support/test_meshes.h"
#include "support/set_level.h"

namespace rgbtest {
namespace {

class DisplayLevels : public testing::TestWithParam<TestMesh> {};

TEST_P(DisplayLevels, AreEachVertexsDisplayLevelDuringBudgetRuns) {
    const TestMesh& base = GetParam();
    rgb::Mesh mesh = make_rgb_mesh(base);
    // Detail to remove first, so that the run frees slots.
    rgbtest::set_level(mesh, 2);
    rgb::LodSettings settings;
    settings.max_triangles = 30 * base.triangles.size();
    rgb::LodDriver driver(mesh, settings);
    std::size_t above_own_level = 0, dead = 0;
    while (!driver.done()) {
        driver.run(base.triangles.size());
        const std::vector<std::uint8_t> levels = rgb::display_levels(mesh);
        ASSERT_EQ(levels.size(), mesh.vertex_capacity());
        rgb::HierarchyEvaluator evaluator(mesh.base());
        for (std::uint32_t i = 0; i < levels.size(); ++i) {
            const rgb::VertexId v(i);
            if (!mesh.is_live(v)) {
                ASSERT_EQ(levels[i], 0) << "dead slot " << i;
                ++dead;
                continue;
            }
            const int k = rgb::display_level(mesh, v);
            ASSERT_EQ(levels[i], k) << "vertex " << i;
            const glm::dvec3 shown = rgb::displayed_position(mesh, v, levels[i]);
            const glm::dvec3 expected = evaluator.control_point(mesh.address(v), k);
            ASSERT_EQ(shown.x, expected.x) << "vertex " << i;
            ASSERT_EQ(shown.y, expected.y) << "vertex " << i;
            ASSERT_EQ(shown.z, expected.z) << "vertex " << i;
            above_own_level += k > mesh.level(v);
        }
    }
    // Vertices shown above their own level (coarser ones amid finer faces) are what the pass must
    // get right, and freed slots what it must skip.
    EXPECT_GT(above_own_level, base.triangles.size() / 2);
    EXPECT_GT(dead, 0u);
}

INSTANTIATE_TEST_SUITE_P(Meshes, DisplayLevels, testing::Values(icosahedron(), perforated_slab(7, 7, 3), grid_with_holes(8, 8, 3)),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace rgbtest
