// A job cuts its pieces further to the time a step has left (down to single base faces, at the pace
// its earlier pieces went), and the mesh is still the one the requests give whole.
#include <chrono>
#include <random>

#include <gtest/gtest.h>

#include "app/request_job.h"
#include "app/request_pieces.h"
#include "rgb/lod/dab.h"
#include "rgb/lod/refine.h"
#include "rgb/mesh/mesh.h"
#include "support/random_operations.h"
#include "support/same_mesh.h"
#include "support/test_meshes.h"

namespace app {
namespace {

TEST(RequestJob, PiecesCutToTheTimeLeftGiveTheMeshOfTheWholeDabs) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::bunny());
    rgb::refine_uniform(mesh, 1);
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    rgb::Mesh whole = mesh;
    RequestJob job(mesh, "stroke", true);
    std::size_t pieces = 0;
    for (int i = 0; i < 12; ++i) {
        rgb::Dab dab;
        dab.mode = static_cast<rgb::BrushMode>(i % 3);
        dab.level = i % 3 == 1 ? static_cast<int>(rng() % 2) : 2 + static_cast<int>(rng() % 2);
        dab.radius = mesh.base().longest_edge() * (2.0 + unit(rng));
        dab.falloff = i % 2 == 0 ? 0.0 : 0.5;
        dab.centre = mesh.base_space_position(rgbtest::random_live_vertex(mesh, rng));
        if (i % 4 != 0) dab.view = glm::dvec3(unit(rng), unit(rng), unit(rng));
        rgb::apply_dab(whole, dab);
        job.add([&mesh, dab, &pieces] {
            std::vector<rgb::LevelRequest> cut = dab_pieces(mesh, dab, 0);
            pieces += cut.size();
            return cut;
        }, "");
    }
    job.close();
    // A step of a microsecond applies one piece: the first of a kind and level on one base face, the
    // next on as many as fit, which is one.
    std::size_t steps = 1;
    while (job.step(std::chrono::microseconds(1))) ++steps;
    EXPECT_TRUE(rgbtest::same_mesh(mesh, whole));
    EXPECT_GT(steps, 2 * pieces) << "the " << pieces << " pieces were cut to single base faces";
}

}  // namespace
}  // namespace app
