// OpenMesh's LoopT (an external implementation with the same original Loop weights) agrees with
// refine_uniform(k) vertex by vertex and face by face. There are no shared identities, so vertices
// are matched by position: each RGB vertex must have exactly one OpenMesh vertex within 1e-12 of the
// bounding-box diagonal, found through a hash grid of much coarser cells.
#include <algorithm>
#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "rgb/lod/refine.h"
#include "rgb/values/loop_geometry.h"
#include "support/openmesh_loop.h"
#include "support/oracle_checks.h"
#include "support/triangle_keys.h"

namespace rgbtest {
namespace {

using Cell = std::array<std::int64_t, 3>;

class PositionIndex {
public:
    PositionIndex(const std::vector<glm::dvec3>& points, double cell_size) : points_(points), cell_size_(cell_size) {
        for (std::uint32_t i = 0; i < points.size(); ++i) cells_[cell_of(points[i])].push_back(i);
    }
    // Indices of the points within `tolerance` of p (tolerance must be below the cell size).
    std::vector<std::uint32_t> near(const glm::dvec3& p, double tolerance) const {
        std::vector<std::uint32_t> found;
        const Cell c = cell_of(p);
        for (std::int64_t dx = -1; dx <= 1; ++dx)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
                for (std::int64_t dz = -1; dz <= 1; ++dz) {
                    const auto it = cells_.find({c[0] + dx, c[1] + dy, c[2] + dz});
                    if (it == cells_.end()) continue;
                    for (std::uint32_t i : it->second)
                        if (glm::distance(points_[i], p) <= tolerance) found.push_back(i);
                }
        return found;
    }

private:
    Cell cell_of(const glm::dvec3& p) const {
        return {static_cast<std::int64_t>(std::floor(p.x / cell_size_)), static_cast<std::int64_t>(std::floor(p.y / cell_size_)),
                static_cast<std::int64_t>(std::floor(p.z / cell_size_))};
    }
    const std::vector<glm::dvec3>& points_;
    double cell_size_;
    std::map<Cell, std::vector<std::uint32_t>> cells_;
};

void expect_agrees_with_openmesh(const TestMesh& base, int max_level) {
    rgb::Mesh mesh = make_rgb_mesh(base);
    const double diagonal = bounding_box_diagonal(base.positions);
    const double tolerance = 1e-12 * diagonal;
    for (int k = 1; k <= max_level; ++k) {
        SCOPED_TRACE(base.name + " at level " + std::to_string(k));
        rgb::refine_uniform(mesh, k);
        const TestMesh reference = openmesh_loop(base, k);
        ASSERT_EQ(mesh.num_vertices(), reference.positions.size());
        ASSERT_EQ(mesh.num_faces(), reference.triangles.size());

        const PositionIndex index(reference.positions, 1e-9 * diagonal);
        std::vector<std::uint32_t> rgb_of_reference(reference.positions.size(), rgb::VertexId::invalid_index);
        for (rgb::VertexId v : mesh.vertices()) {
            const glm::dvec3 p = rgb::displayed_position(mesh, v);
            const std::vector<std::uint32_t> near = index.near(p, tolerance);
            ASSERT_EQ(near.size(), 1u) << "vertex " << v.idx << " at (" << p.x << ", " << p.y << ", " << p.z
                                       << ") matches " << near.size() << " OpenMesh vertices";
            ASSERT_EQ(rgb_of_reference[near[0]], rgb::VertexId::invalid_index) << "OpenMesh vertex matched twice";
            rgb_of_reference[near[0]] = v.idx;
        }
        std::vector<rgb::Triangle> got, want;
        for (rgb::FaceId f : mesh.faces()) {
            const auto& v = mesh.face_vertices(f);
            got.push_back(canonical_rotation(rgb::Triangle{v[0].idx, v[1].idx, v[2].idx}));
        }
        for (const rgb::Triangle& t : reference.triangles)
            want.push_back(canonical_rotation(
                rgb::Triangle{rgb_of_reference[t[0]], rgb_of_reference[t[1]], rgb_of_reference[t[2]]}));
        std::sort(got.begin(), got.end());
        std::sort(want.begin(), want.end());
        EXPECT_TRUE(got == want) << "connectivity differs from OpenMesh";
    }
}

class OpenMeshAgreement : public testing::TestWithParam<TestMesh> {};

TEST_P(OpenMeshAgreement, LoopTEqualsRefineUniformToLevel4) { expect_agrees_with_openmesh(GetParam(), 4); }

INSTANTIATE_TEST_SUITE_P(SmallMeshes, OpenMeshAgreement, testing::ValuesIn(small_meshes()),
                         [](const testing::TestParamInfo<TestMesh>& info) { return info.param.name; });

TEST(OpenMeshAgreementBunny, LoopTEqualsRefineUniformToLevel3) { expect_agrees_with_openmesh(bunny(), 3); }

}  // namespace
}  // namespace rgbtest
