// Work cut into pieces gives the mesh the work gives whole: dabs of every mode, with falloff and a
// view direction, cut into levels and batches of base faces as finely as the pieces go, whatever
// level they start from; and "set all" cut the same way.
#include <random>

#include <gtest/gtest.h>

#include "app/request_pieces.h"
#include "rgb/lod/dab.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/mesh.h"
#include "support/random_operations.h"
#include "support/same_mesh.h"
#include "support/test_meshes.h"
#include "support/set_level.h"

namespace app {
namespace {

rgb::RequestStats apply_all(rgb::Mesh& mesh, const std::vector<rgb::LevelRequest>& pieces) {
    rgb::RequestStats stats;
    for (const rgb::LevelRequest& piece : pieces) stats += rgb::apply_request(mesh, piece);
    return stats;
}

// Random dabs cut into pieces. Under the sanitizers (test code at -O0 over an instrumented core, where
// this test was a tenth of the editor tests) 12 rather than 30: still every mode, view and falloff.
#if defined(__SANITIZE_ADDRESS__)
constexpr int kPieceDabs = 12;
#else
constexpr int kPieceDabs = 30;
#endif

TEST(RequestPieces, ADabInPiecesGivesTheMeshOfTheWholeDab) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::bunny());
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::size_t sliced = 0;
    for (int i = 0; i < kPieceDabs; ++i) {
        rgb::Dab dab;
        dab.mode = static_cast<rgb::BrushMode>(i % 3);
        dab.level = 1 + static_cast<int>(rng() % 5);
        dab.radius = mesh.base().longest_edge() * (1.0 + 0.9 * unit(rng));
        dab.falloff = i % 2 == 0 ? 0.0 : 0.5 + 0.5 * unit(rng);
        dab.centre = mesh.base_space_position(rgbtest::random_live_vertex(mesh, rng));
        if (i % 4 != 0) dab.view = glm::dvec3(unit(rng), unit(rng), unit(rng));
        const int from_level = static_cast<int>(rng() % 4);
        // 64 triangles a piece: every dab of some size is cut, down to single base faces.
        const std::vector<rgb::LevelRequest> pieces = dab_pieces(mesh, dab, from_level, 64.0);
        sliced += pieces.size() > 1;
        rgb::Mesh whole = mesh;
        const rgb::RequestStats expected = rgb::apply_dab(whole, dab);
        const rgb::RequestStats stats = apply_all(mesh, pieces);
        ASSERT_TRUE(rgbtest::same_mesh(mesh, whole)) << "dab " << i << " in " << pieces.size() << " pieces";
        EXPECT_EQ(stats.splits > 0 || stats.removals > 0, expected.splits > 0 || expected.removals > 0) << "dab " << i;
    }
    EXPECT_GT(2 * sliced, std::size_t{kPieceDabs}) << "most dabs must have been cut";
}

TEST(RequestPieces, RefinePiecesGoCoarseToFine) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::bunny());
    const rgb::Dab dab{rgb::BrushMode::Refine, 4, 2.0 * mesh.base().longest_edge(), 0.5, mesh.base_space_position(rgb::VertexId(0)), std::nullopt};
    const std::vector<rgb::LevelRequest> pieces = dab_pieces(mesh, dab, 0, 256.0);
    ASSERT_GT(pieces.size(), 4u);
    for (std::size_t i = 1; i < pieces.size(); ++i) EXPECT_LE(pieces[i - 1].level, pieces[i].level);
    EXPECT_EQ(pieces.front().level, 1);
    EXPECT_EQ(pieces.back().level, 4);
}

TEST(RequestPieces, SetAllInPiecesIsSetLevel) {
    for (int level : {2, 0, 3, 1}) {
        rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::icosahedron());
        rgbtest::set_level(mesh, 1, rgb::Sphere{glm::dvec3(0.0, 0.0, 1.0), 0.8});
        rgbtest::set_level(mesh, 4, rgb::Sphere{glm::dvec3(1.0, 0.0, 0.0), 0.5});
        rgb::Mesh whole = mesh;
        rgbtest::set_level(whole, level);
        const std::vector<rgb::LevelRequest> pieces = set_all_pieces(mesh, level, 16.0);
        EXPECT_GT(pieces.size(), 2u);
        apply_all(mesh, pieces);
        EXPECT_TRUE(rgbtest::same_mesh(mesh, whole)) << "level " << level;
    }
}

}  // namespace
}  // namespace app
