// The picking index against the obvious second implementation: every live slot tested along the ray.
// Rays from all around an adaptive mesh must find the same triangle at the same distance, before and
// after edits that the index follows through the mesh's observer.
#include <cmath>
#include <optional>
#include <random>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "app/surface_index.h"
#include "render/mesh_changes.h"
#include "render/surface_geometry.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/mesh.h"
#include "support/random_operations.h"
#include "support/test_meshes.h"
#include "support/set_level.h"

namespace app {
namespace {

// Under the sanitizers (test code at -O0) the slot-by-slot picks were the largest part of the editor
// tests; there a quarter of the rays are cast, after the same edits, which is what the sanitizers
// watch. The Release build casts them all.
#if defined(__SANITIZE_ADDRESS__)
constexpr int kRayDivisor = 4;
#else
constexpr int kRayDivisor = 1;
#endif

std::optional<SurfaceHit> pick_every_slot(const render::SurfaceGeometry& geometry, const Ray& ray) {
    std::optional<SurfaceHit> best;
    for (std::uint32_t slot = 0; slot < geometry.face_slots(); ++slot) {
        if ((geometry.vertices()[3 * slot].code & render::kCodeLiveBit) == 0) continue;
        const std::optional<double> d = front_hit(ray, geometry.corners(rgb::FaceId(slot)));
        if (d && (!best || *d < best->distance)) best = SurfaceHit{rgb::FaceId(slot), ray.origin + *d * ray.direction, *d};
    }
    return best;
}

// Rays from points on a sphere around the mesh towards random points near its vertices.
void expect_same_picks(const rgb::Mesh& mesh, const render::SurfaceGeometry& geometry, const SurfaceIndex& index,
                       std::mt19937& rng, int rays) {
    const render::BoundingSphere bounds = geometry.bounds(mesh);
    std::normal_distribution<double> normal;
    int hits = 0;
    rays /= kRayDivisor;
    for (int i = 0; i < rays; ++i) {
        const glm::dvec3 direction = glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng)));
        const glm::dvec3 eye = glm::dvec3(bounds.centre) + 3.0 * static_cast<double>(bounds.radius) * direction;
        const glm::dvec3 target = mesh.base_space_position(rgbtest::random_live_vertex(mesh, rng)) +
                                  0.05 * static_cast<double>(bounds.radius) * glm::dvec3(normal(rng), normal(rng), normal(rng));
        const Ray ray{eye, glm::normalize(target - eye)};
        const std::optional<SurfaceHit> expected = pick_every_slot(geometry, ray);
        const std::optional<SurfaceHit> found = index.pick(geometry, ray);
        ASSERT_EQ(found.has_value(), expected.has_value()) << "ray " << i;
        if (!expected) continue;
        ++hits;
        // The same distance bit for bit; a different face only where the ray meets a shared edge.
        EXPECT_EQ(found->distance, expected->distance) << "ray " << i;
        if (found->face != expected->face) {
            const auto a = geometry.corners(found->face), b = geometry.corners(expected->face);
            int shared = 0;
            for (const glm::dvec3& p : a) shared += p == b[0] || p == b[1] || p == b[2];
            EXPECT_GE(shared, 1) << "ray " << i << " found a face that is not the nearest";
        }
    }
    EXPECT_GT(hits, rays / 3) << "the rays must mostly hit the mesh";
}

TEST(SurfaceIndex, PicksWhatTestingEverySlotPicksAndFollowsEdits) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::bunny());
    std::mt19937 rng(11);
    // Levels 0 to 4 side by side, so the index holds triangles of many sizes.
    for (int i = 0; i < 6; ++i)
        rgbtest::set_level(mesh, 1 + i % 4,
                       rgb::Sphere{mesh.base_space_position(rgbtest::random_live_vertex(mesh, rng)), 2.0 * mesh.base().longest_edge()});
    render::MeshChanges changes(mesh);
    render::SurfaceGeometry geometry;
    geometry.rebuild(mesh);
    changes.clear();
    SurfaceIndex index;
    index.rebuild(mesh, geometry);
    expect_same_picks(mesh, geometry, index, rng, 200);

    for (int i = 0; i < 4; ++i) {
        rgb::LevelRequest request;
        request.kind = i % 2 == 0 ? rgb::RequestKind::Coarsen : rgb::RequestKind::Refine;
        request.level = i % 2 == 0 ? 0 : 4;
        request.sphere = rgb::Sphere{mesh.base_space_position(rgbtest::random_live_vertex(mesh, rng)), 3.0 * mesh.base().longest_edge()};
        rgb::apply_request(mesh, request);
        index.update(geometry, geometry.update(mesh, changes));
        changes.clear();
        expect_same_picks(mesh, geometry, index, rng, 60);
    }
}

}  // namespace
}  // namespace app
