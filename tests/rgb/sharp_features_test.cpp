// Crease and corner tags on the base mesh (issue 13, docs/loop-creases.md §1-§2, §4.4): how they are
// checked and normalised, the boundary option, the rule regimes they give each vertex, and the dart
// masks against the exact fractions of the note. Agreement of the refined surfaces with OpenSubdiv is
// tests/oracle/sharp_refinement_test.cpp.
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "rgb/mesh/base_mesh.h"
#include "rgb/mesh/sharp_angle.h"
#include "rgb/mesh/vertex_rules.h"
#include "rgb/rules/dart_masks.h"
#include "support/obj_reader.h"
#include "support/test_meshes.h"

namespace rgbtest {
namespace {

rgb::BaseMesh tagged(const TestMesh& m, const rgb::SharpFeatures& f) { return rgb::BaseMesh(m.positions, m.triangles, f); }

// The address of base vertex v, in any face that has it.
rgb::SurfacePoint vertex_point(const TestMesh& m, std::uint32_t v) {
    for (std::uint32_t f = 0; f < m.triangles.size(); ++f)
        for (int c = 0; c < 3; ++c)
            if (m.triangles[f][c] == v) return rgb::corner_point(f, c);
    throw std::logic_error("no such vertex");
}

TEST(SharpFeatures, TagsAreNormalisedLaterOnesWinAndZeroIsDropped) {
    rgb::SharpFeatures f;
    f.edges = {{1, 0, 3}, {6, 1, 10}, {0, 1, 12}, {2, 5, 2}, {5, 2, 0}};
    f.corners = {{4, 2}, {3, 5}, {4, 0}};
    const rgb::BaseMesh base = tagged(bipyramid(5), f);
    const std::vector<rgb::EdgeSharpness> edges{{0, 1, 10}, {1, 6, 10}};
    const std::vector<rgb::VertexSharpness> corners{{3, 5}};
    EXPECT_EQ(base.sharp_features().edges, edges);
    EXPECT_EQ(base.sharp_features().corners, corners);
    EXPECT_TRUE(base.has_sharp_features());
}

TEST(SharpFeatures, BadTagsAreRefusedWithTheirName) {
    const TestMesh m = bipyramid(5);
    auto refused = [&](const rgb::SharpFeatures& f, const std::string& want) {
        try {
            tagged(m, f);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what()).find(want) != std::string::npos;
        }
        return false;
    };
    rgb::SharpFeatures missing_edge, missing_vertex, negative, missing_corner;
    missing_edge.edges = {{0, 2, 10}};  // the equator's vertices 0 and 2 are not neighbours
    missing_vertex.edges = {{0, 70, 10}};
    negative.edges = {{0, 1, -1}};
    missing_corner.corners = {{7, 10}};
    EXPECT_TRUE(refused(missing_edge, "crease 0-2 is not an edge"));
    EXPECT_TRUE(refused(missing_vertex, "crease 0-70 uses a missing vertex"));
    EXPECT_TRUE(refused(negative, "negative sharpness"));
    EXPECT_TRUE(refused(missing_corner, "corner 7 is a missing vertex"));
}

TEST(SharpFeatures, BoundaryEdgesAreInfinitelySharpAndEdgeAndCornerMakesSingleFaceVerticesCorners) {
    const TestMesh m = grid(3, 2);  // vertices (3, 0) and (0, 2), 3 and 8, have a single face
    const rgb::BaseMesh plain(m.positions, m.triangles);
    EXPECT_FALSE(plain.has_sharp_features());
    for (std::uint32_t h = 0; h < 3 * m.triangles.size(); ++h)
        EXPECT_EQ(plain.edge_sharpness(h), plain.opposite(h) == rgb::BaseMesh::kNone ? rgb::kInfiniteSharpness : 0);
    rgb::SharpFeatures f;
    f.boundary = rgb::BoundaryInterpolation::EdgeAndCorner;
    const rgb::BaseMesh cornered = tagged(m, f);
    EXPECT_TRUE(cornered.has_sharp_features());
    for (std::uint32_t v = 0; v < m.positions.size(); ++v) {
        const bool single_face = v == 3 || v == 8;
        EXPECT_EQ(cornered.corner_sharpness(v), single_face ? rgb::kInfiniteSharpness : 0) << v;
        EXPECT_EQ(rgb::vertex_regimes(cornered, vertex_point(m, v))[0].rule,
                  single_face ? rgb::VertexRule::Corner
                              : (cornered.is_boundary_vertex(v) ? rgb::VertexRule::Crease : rgb::VertexRule::Smooth))
            << v;
    }
}

TEST(SharpFeatures, RegimesChangeWhereSemiSharpTagsRunOut) {
    // Apex 5 of a pentagonal bipyramid: edges to 0 (infinite), 2 and 3 (sharpness 1): a corner at
    // level 0, a dart along 5-0 from level 1 on. Equator vertex 0: edges to 5 (infinite) and 1
    // (sharpness 3): a crease until level 3, then a dart along 0-5.
    const TestMesh m = bipyramid(5);
    rgb::SharpFeatures f;
    f.edges = {{5, 0, 10}, {5, 2, 1}, {5, 3, 1}, {0, 1, 3}};
    const rgb::BaseMesh base = tagged(m, f);
    auto ring_index = [&](std::uint32_t centre, std::uint32_t neighbour) {
        const auto ring = rgb::ring_at(base, vertex_point(m, centre), 0);
        for (std::uint32_t i = 0; i < ring.size(); ++i)
            if (rgb::base_vertex(base, ring[i]) == neighbour) return i;
        throw std::logic_error("not a neighbour");
    };
    const rgb::Regimes apex = rgb::vertex_regimes(base, vertex_point(m, 5));
    ASSERT_EQ(apex.size(), 2u);
    EXPECT_EQ(apex[0].start, 0);
    EXPECT_EQ(apex[0].rule, rgb::VertexRule::Corner);
    EXPECT_EQ(apex[1].start, 1);
    EXPECT_EQ(apex[1].rule, rgb::VertexRule::Dart);
    EXPECT_EQ(apex[1].sharp[0], ring_index(5, 0));
    const rgb::Regimes equator = rgb::vertex_regimes(base, vertex_point(m, 0));
    ASSERT_EQ(equator.size(), 2u);
    EXPECT_EQ(equator[0].rule, rgb::VertexRule::Crease);
    EXPECT_EQ(std::min(equator[0].sharp[0], equator[0].sharp[1]), std::min(ring_index(0, 5), ring_index(0, 1)));
    EXPECT_EQ(std::max(equator[0].sharp[0], equator[0].sharp[1]), std::max(ring_index(0, 5), ring_index(0, 1)));
    EXPECT_EQ(equator[1].start, 3);
    EXPECT_EQ(equator[1].rule, rgb::VertexRule::Dart);
    EXPECT_EQ(equator[1].sharp[0], ring_index(0, 5));

    // The midpoint of 0-1 (level 1) is a crease vertex for levels 1 and 2, then smooth; a vertex
    // inserted on it at level 3 is the midpoint of an edge of sharpness 1 and smooth itself.
    rgb::SurfacePoint mid = rgb::midpoint(base, vertex_point(m, 0), vertex_point(m, 1));
    const rgb::Regimes edge_vertex = rgb::vertex_regimes(base, mid);
    ASSERT_EQ(edge_vertex.size(), 2u);
    EXPECT_EQ(edge_vertex[0].start, 1);
    EXPECT_EQ(edge_vertex[0].rule, rgb::VertexRule::Crease);
    EXPECT_EQ(edge_vertex[1].start, 3);
    EXPECT_EQ(edge_vertex[1].rule, rgb::VertexRule::Smooth);
    for (int l = 2; l <= 3; ++l) mid = rgb::midpoint(base, vertex_point(m, 0), mid);
    EXPECT_EQ(mid.level, 3);
    EXPECT_TRUE(rgb::inserted_at_midpoint(base, mid));
    EXPECT_EQ(rgb::vertex_regimes(base, mid)[0].rule, rgb::VertexRule::Smooth);
    EXPECT_FALSE(rgb::follows_untagged_rules(base, vertex_point(m, 5)));
    EXPECT_TRUE(rgb::follows_untagged_rules(base, mid));
}

// assets/machined_part.obj (made by make_machined_part.py): every wall meets the caps and its
// neighbours at 90 degrees, the chamfer meets its two walls at 45; every other edge is flat. Seven
// upright corners of two edges each and two rims of fifteen: 40 edges at 90 degrees, 4 at 45.
TEST(SharpAngle, MachinedPartEdgesAreTaggedByTheirDihedralAngle) {
    const TestMesh part = read_obj(RGBSUB_ASSETS_DIR "/machined_part.obj");
    const rgb::BaseMesh base(part.positions, part.triangles);
    std::size_t right = 0, chamfer = 0, flat = 0;
    for (std::uint32_t h = 0; h < 3 * part.triangles.size(); ++h) {
        if (base.opposite(h) < h) continue;
        const double angle = rgb::dihedral_angle_degrees(base, h);
        right += std::abs(angle - 90.0) < 1e-9;
        chamfer += std::abs(angle - 45.0) < 1e-9;
        flat += std::abs(angle) < 1e-9;
    }
    EXPECT_EQ(right, 40u);
    EXPECT_EQ(chamfer, 4u);
    EXPECT_EQ(right + chamfer + flat, 3 * part.triangles.size() / 2) << "the part is closed";
    EXPECT_EQ(rgb::edges_sharper_than(base, 30.0).size(), 44u);
    EXPECT_EQ(rgb::edges_sharper_than(base, 60.0).size(), 40u);
    EXPECT_EQ(rgb::edges_sharper_than(base, 100.0).size(), 0u);
    EXPECT_EQ(rgb::edges_sharper_than(base, 0.0).size(), 44u) << "a flat edge has angle 0, not above 0";
    for (const rgb::EdgeSharpness& e : rgb::edges_sharper_than(base, 30.0)) {
        EXPECT_LT(e.a, e.b);
        EXPECT_EQ(e.sharpness, rgb::kInfiniteSharpness);
    }
}

// docs/loop-creases.md §4.4: where beta_n is rational the dart's limit mask is too.
TEST(DartMasks, LimitMasksAreTheExactFractions) {
    const struct {
        int n;
        std::vector<double> centre_then_from_sharp;  // centre, v_s, v_s±1, v_s±2, ...
    } cases[] = {
        {3, {16.0 / 37, 9.0 / 37, 6.0 / 37}},
        {4, {2944.0 / 6385, 217.0 / 1277, 744.0 / 6385, 868.0 / 6385}},
        {6, {110.0 / 213, 7.0 / 71, 29.0 / 426, 35.0 / 426, 6.0 / 71}},
    };
    for (const auto& c : cases) {
        const std::vector<double> mask = rgb::dart_limit_mask(c.n);
        ASSERT_EQ(mask.size(), static_cast<std::size_t>(c.n) + 1);
        EXPECT_NEAR(mask[0], c.centre_then_from_sharp[0], 1e-15) << c.n;
        for (int i = 0; i < c.n; ++i) {
            const int away = std::min(i, c.n - i);  // ring steps from the sharp edge, either way round
            EXPECT_NEAR(mask[1 + i], c.centre_then_from_sharp[1 + away], 1e-15) << c.n << " " << i;
        }
    }
}

TEST(DartMasks, OneStepIsTheSmoothVertexRule) {
    // beta_3 = 3/16: the centre keeps 7/16.
    const std::vector<double> step = rgb::dart_mask(3, 1);
    const std::vector<double> want{7.0 / 16, 3.0 / 16, 3.0 / 16, 3.0 / 16};
    EXPECT_EQ(step, want);
    EXPECT_EQ(rgb::dart_mask(5, 0), (std::vector<double>{1, 0, 0, 0, 0, 0}));
}

}  // namespace
}  // namespace rgbtest
