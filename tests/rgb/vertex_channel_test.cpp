// Vertex colours subdivide as positions do (issue 12): a channel's values on an adaptive mesh equal,
// bit for bit, the positions of the same adaptive mesh built over a base mesh whose positions are the
// channel's values. The two meshes go through the same operators (chosen by slot, which geometry does
// not influence), so they have the same vertices in the same slots.
#include <memory>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "rgb/lod/refine.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/operators.h"
#include "rgb/values/hierarchy_evaluator.h"
#include "rgb/values/loop_geometry.h"
#include "rgb/values/loop_split.h"
#include "rgb/values/restore_state.h"
#include "rgb/values/vertex_channel.h"
#include "support/test_meshes.h"

namespace {

using rgbtest::TestMesh;

struct ChannelCase {
    TestMesh mesh;
    rgb::SharpFeatures features;
};

void PrintTo(const ChannelCase& c, std::ostream* os) { *os << c.mesh.name << (c.features == rgb::SharpFeatures{} ? "" : " tagged"); }

std::vector<ChannelCase> channel_cases() {
    rgb::SharpFeatures icosahedron_tags;
    icosahedron_tags.edges = {{0, 1, rgb::kInfiniteSharpness}, {1, 2, 2}};
    icosahedron_tags.corners = {{5, rgb::kInfiniteSharpness}};
    rgb::SharpFeatures grid_tags;
    grid_tags.boundary = rgb::BoundaryInterpolation::EdgeAndCorner;
    return {{rgbtest::icosahedron(), {}}, {rgbtest::grid(3, 3), {}}, {rgbtest::fan(6), {}},
            {rgbtest::icosahedron(), icosahedron_tags}, {rgbtest::grid(3, 3), grid_tags}};
}

// Colours unrelated to the positions (and not a linear function of them).
std::vector<glm::dvec3> random_colours(std::size_t n, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<glm::dvec3> colours(n);
    for (glm::dvec3& c : colours) c = {unit(rng), unit(rng), unit(rng)};
    return colours;
}

class VertexChannel : public ::testing::TestWithParam<ChannelCase> {};

// A case's mesh, random colours for its base vertices, and the mesh over a base whose positions are them.
struct ChannelMeshes {
    ChannelMeshes(const ChannelCase& c, std::uint32_t seed)
        : colours(random_colours(c.mesh.positions.size(), seed)),
          mesh(std::make_shared<const rgb::BaseMesh>(c.mesh.positions, c.mesh.triangles, c.features)),
          over_colours(std::make_shared<const rgb::BaseMesh>(colours, c.mesh.triangles, c.features)) {}
    std::vector<glm::dvec3> colours;
    rgb::Mesh mesh, over_colours;
};

// Uniform refinement to `start_level`, then 300 random splits and removals, the same by slot on
// `mesh` and `over_colours`; check(step) every 50 steps.
template <class Check>
void random_edits(ChannelMeshes& meshes, int start_level, const Check& check) {
    rgb::Mesh &mesh = meshes.mesh, &over_colours = meshes.over_colours;
    rgb::refine_uniform(mesh, start_level);
    rgb::refine_uniform(over_colours, start_level);
    std::mt19937 rng(11);
    for (int step = 0; step < 300; ++step) {
        std::vector<rgb::FaceId> faces;
        for (rgb::FaceId f : mesh.faces()) faces.push_back(f);
        const rgb::FaceId f = faces[rng() % faces.size()];
        const rgb::HalfedgeId h = rgb::Mesh::halfedge(f, static_cast<int>(rng() % 3));
        const rgb::VertexId v = mesh.face_vertices(f)[rng() % 3];
        if (rng() % 4 != 0 && rgb::can_split_edge(mesh, h) && mesh.edge_type(h).level < 4) {
            rgb::split_edge(mesh, h);
            rgb::split_edge(over_colours, h);
        } else if (mesh.level(v) > 0 && rgb::can_remove_vertex(mesh, v)) {
            rgb::remove_vertex(mesh, v);
            rgb::remove_vertex(over_colours, v);
        }
        ASSERT_EQ(mesh.num_vertices(), over_colours.num_vertices());
        if (step % 50 == 49) check(step);
    }
}

TEST_P(VertexChannel, ValuesAreThePositionsOfTheMeshOverTheChannelsBase) {
    ChannelMeshes meshes(GetParam(), 7);
    const auto& [colours, mesh, over_colours] = meshes;
    std::size_t checks = 0;
    random_edits(meshes, 0, [&](int step) {
        const std::vector<glm::dvec3> displayed = rgb::vertex_channel_values(mesh, colours, rgb::ChannelLevel::Displayed);
        const std::vector<glm::dvec3> limit = rgb::vertex_channel_values(mesh, colours, rgb::ChannelLevel::Limit);
        for (rgb::VertexId w : mesh.vertices()) {
            ASSERT_TRUE(over_colours.is_live(w));
            ASSERT_EQ(displayed[w.idx], rgb::displayed_position(over_colours, w)) << "vertex " << w.idx << " step " << step;
            ASSERT_EQ(limit[w.idx], rgb::limit_position_uncached(over_colours, w)) << "vertex " << w.idx << " step " << step;
            ++checks;
        }
    });
    EXPECT_GT(checks, 100u);
}

// The channel's values come from one linear pass over the vertex set (hierarchy_positions.h); the
// hierarchy evaluator computes each vertex alone from the base mesh, by the rules of each regime.
TEST_P(VertexChannel, ValuesAreTheHierarchyEvaluatorsOverTheChannelsBase) {
    ChannelMeshes meshes(GetParam(), 5);
    const auto& [colours, mesh, over_colours] = meshes;
    std::size_t checks = 0, above_own_level = 0;
    // From level 2: most vertices are then displayed above their own level, by the closed form of §4.2.
    random_edits(meshes, 2, [&](int step) {
        const std::vector<glm::dvec3> displayed = rgb::vertex_channel_values(mesh, colours, rgb::ChannelLevel::Displayed);
        const std::vector<glm::dvec3> limit = rgb::vertex_channel_values(mesh, colours, rgb::ChannelLevel::Limit);
        rgb::HierarchyEvaluator evaluator(over_colours.base());
        for (rgb::VertexId w : mesh.vertices()) {
            const int k = rgb::display_level(mesh, w);
            ASSERT_EQ(displayed[w.idx], evaluator.control_point(mesh.address(w), k)) << "vertex " << w.idx << " step " << step;
            ASSERT_EQ(limit[w.idx], evaluator.limit_position(mesh.address(w))) << "vertex " << w.idx << " step " << step;
            above_own_level += k > mesh.level(w);
            ++checks;
        }
    });
    EXPECT_GT(checks, 100u);
    EXPECT_GT(above_own_level, 50u);
}

// A saved mesh restored with its channel (rgb::RestoredChannel) gets the channel's values from the
// restore's own pass; restored vertex i is the i-th live slot (state.h).
TEST_P(VertexChannel, RestoringWithTheChannelGivesThePositionsOfTheMeshOverTheChannelsBase) {
    ChannelMeshes meshes(GetParam(), 3);
    const auto& [colours, mesh, over_colours] = meshes;
    std::size_t checks = 0;
    random_edits(meshes, 1, [&](int step) {
        const rgb::MeshState state = rgb::capture_state(mesh);
        rgb::RestoredChannel displayed{colours, rgb::ChannelLevel::Displayed, {}}, limit{colours, rgb::ChannelLevel::Limit, {}};
        const rgb::Mesh restored = rgb::restore_state(state, {}, &displayed);
        rgb::restore_state(state, {}, &limit);
        ASSERT_EQ(displayed.values.size(), mesh.num_vertices());
        ASSERT_EQ(limit.values.size(), mesh.num_vertices());
        std::size_t i = 0;
        for (rgb::VertexId w : mesh.vertices()) {
            ASSERT_EQ(displayed.values[i], rgb::displayed_position(over_colours, w)) << "vertex " << w.idx << " step " << step;
            ASSERT_EQ(limit.values[i], rgb::limit_position_uncached(over_colours, w)) << "vertex " << w.idx << " step " << step;
            // The positions are the restore's own, whatever channel goes along.
            ASSERT_EQ(rgb::displayed_position(restored, rgb::VertexId(static_cast<std::uint32_t>(i))), rgb::displayed_position(mesh, w));
            ++i;
            ++checks;
        }
    });
    EXPECT_GT(checks, 100u);
}

TEST_P(VertexChannel, PositionsAsAChannelGiveThePositions) {
    const ChannelCase& c = GetParam();
    rgb::Mesh mesh(std::make_shared<const rgb::BaseMesh>(c.mesh.positions, c.mesh.triangles, c.features));
    rgb::refine_uniform(mesh, 3);
    const std::vector<glm::dvec3> displayed = rgb::vertex_channel_values(mesh, c.mesh.positions, rgb::ChannelLevel::Displayed);
    for (rgb::VertexId v : mesh.vertices()) ASSERT_EQ(displayed[v.idx], rgb::displayed_position(mesh, v)) << "vertex " << v.idx;
}

TEST(VertexChannelInput, OneValuePerBaseVertex) {
    const TestMesh m = rgbtest::octahedron();
    const rgb::Mesh mesh = rgbtest::make_rgb_mesh(m);
    const std::vector<glm::dvec3> too_few(m.positions.size() - 1);
    EXPECT_THROW(rgb::vertex_channel_values(mesh, too_few, rgb::ChannelLevel::Displayed), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Meshes, VertexChannel, ::testing::ValuesIn(channel_cases()));

}  // namespace
