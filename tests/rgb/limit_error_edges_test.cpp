// The tolerance criterion's values (rgb/lod/limit_error.h), which it computes once per triangle for
// its three edges and shares between them, against the definition evaluated edge by edge: for each
// triangle beside the edge, every way the rest of the mesh can show it with the edge unsplit (either
// other edge split, each corner fine or coarse), every sample of Σ(l+2) against its limit point,
// through the hierarchy evaluator and rgb::interpolate. Exactly, bit for bit, for every edge of Σ0 to
// Σ1 or Σ2 on small meshes, including one whose triangles have two corners at one position (where the
// order in which interpolate sums tied corners is the order they are listed in).
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "rgb/lod/limit_error.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/hierarchy_evaluator.h"
#include "rgb/values/hierarchy_triangle.h"
#include "support/set_level.h"
#include "support/test_meshes.h"

namespace rgbtest {
namespace {

using Weights = rgb::SampleWeights;  // over 4, on the triangle (X0, X1, X2)
using Piece = std::array<Weights, 3>;

constexpr Weights kX0{4, 0, 0}, kX1{0, 4, 0}, kX2{0, 0, 4}, kM12{0, 2, 2}, kM20{2, 0, 2};

// The pieces of level l of T = (X0, X1, X2) with X0X1 unsplit (spec §1.3), for X1X2 and X2X0 split
// or not; with both split, the corner triangle (M12, X2, M20) is left out and the quadrilateral is
// cut from X1 to M20 (spec §3.5). Listed as limit_error.h takes them: a sample on a cut is in the first.
std::vector<std::vector<Piece>> tilings(bool beside_the_edge) {
    std::vector<std::vector<Piece>> all{{{kX0, kX1, kX2}},
                                        {{kM12, kX2, kX0}, {kM12, kX0, kX1}},
                                        {{kM20, kX0, kX1}, {kM20, kX1, kX2}},
                                        {{kX1, kM12, kM20}, {kX1, kM20, kX0}}};
    if (beside_the_edge) all.erase(all.begin(), all.begin() + 3);
    return all;
}

long long signed_area(const Weights& p, const Weights& q, const Weights& r) {
    return static_cast<long long>(q[1] - p[1]) * (r[2] - p[2]) - static_cast<long long>(q[2] - p[2]) * (r[1] - p[1]);
}

// The value of the edge (a, b) of Σl by the definition, one edge and one way of showing at a time.
double value_by_definition(rgb::HierarchyEvaluator& evaluator, const rgb::BaseMesh& base, const rgb::SurfacePoint& a,
                           const rgb::SurfacePoint& b, double tolerance, bool beside_the_edge) {
    double worst = 0.0;
    for (const rgb::HierarchyTriangle& t : rgb::triangles_beside(base, a, b)) {
        // Each node fine and coarse (a midpoint has no coarser position).
        auto shown = [&](const Weights& node, bool coarse) {
            const rgb::SurfacePoint p = t.sample(node);
            const bool corner = std::count(node.begin(), node.end(), 0) == 2;
            if (!corner) return evaluator.control_point(p, p.level);
            if (coarse)
                for (int k = p.level; k < t.level; ++k)
                    if (glm::distance(evaluator.control_point(p, k), evaluator.limit_position(p)) <= tolerance)
                        return evaluator.control_point(p, k);
            return evaluator.control_point(p, t.level);
        };
        std::map<std::pair<Weights, bool>, glm::dvec3> positions;
        for (const Weights& node : {kX0, kX1, kX2, kM12, kM20})
            for (bool coarse : {false, true}) positions[{node, coarse}] = shown(node, coarse);
        std::map<Weights, glm::dvec3> limits;
        for (const Weights& q : rgb::sample_weights()) limits[q] = evaluator.limit_position(t.sample(q));
        for (const std::vector<Piece>& tiling : tilings(beside_the_edge))
            for (const Weights& q : rgb::sample_weights()) {
                const auto piece = std::find_if(tiling.begin(), tiling.end(), [&](const Piece& p) {
                    return signed_area(q, p[1], p[2]) >= 0 && signed_area(p[0], q, p[2]) >= 0 && signed_area(p[0], p[1], q) >= 0;
                });
                if (piece == tiling.end()) continue;
                const Piece& p = *piece;
                const double area = double(signed_area(p[0], p[1], p[2]));
                const std::array<double, 3> weights{double(signed_area(q, p[1], p[2])) / area, double(signed_area(p[0], q, p[2])) / area,
                                                    double(signed_area(p[0], p[1], q)) / area};
                const glm::dvec3& limit = limits.at(q);
                for (int choice = 0; choice < 8; ++choice) {
                    std::array<glm::dvec3, 3> at;
                    bool counted = true;  // each way once: coarse only for corners the sample depends on
                    for (std::size_t i = 0; i < 3; ++i) {
                        const bool coarse = (choice >> i) & 1;
                        const bool corner = std::count(p[i].begin(), p[i].end(), 0) == 2;
                        if (coarse && (!corner || weights[i] == 0.0)) counted = false;
                        at[i] = positions.at({p[i], coarse});
                    }
                    if (counted) worst = std::max(worst, glm::distance(rgb::interpolate(at, weights), limit));
                }
            }
    }
    return worst;
}

// Every edge of Σ0 to Σfinest of `m`, its criterion's value against the definition's.
void expect_values_by_definition(const TestMesh& m, int finest, double share, rgb::LimitErrorCriterion::Samples samples) {
    SCOPED_TRACE(m.name + ", tolerance " + std::to_string(share));
    const double tolerance = share * bounding_box_diagonal(m.positions);
    for (int level = 0; level <= finest; ++level) {
        rgb::Mesh mesh = make_rgb_mesh(m);
        set_level(mesh, level);
        rgb::LimitErrorCriterion criterion(mesh.shared_base(), tolerance, samples);
        rgb::HierarchyEvaluator evaluator(mesh.base());
        std::size_t edges = 0;
        for (rgb::FaceId f : mesh.faces())
            for (int i = 0; i < 3; ++i) {
                const rgb::HalfedgeId h = rgb::Mesh::halfedge(f, i);
                const rgb::SurfacePoint a = mesh.address(mesh.from_vertex(h)), b = mesh.address(mesh.to_vertex(h));
                const double expected =
                    value_by_definition(evaluator, mesh.base(), a, b, tolerance, samples == rgb::LimitErrorCriterion::Samples::BesideTheEdge);
                ASSERT_EQ(criterion.value(a, b), expected) << "level " << level << ", face " << f.idx << ", edge " << i;
                ++edges;
            }
        EXPECT_EQ(edges, 3 * mesh.num_faces());
    }
}

// A mesh whose triangles have two corners at one position: a grid with one vertex moved onto its
// neighbour in x, so that the tied corners sort after the third (where their order shows in the sum).
TestMesh grid_with_tied_corners() {
    TestMesh m = grid(4, 2);
    m.name = "grid with tied corners";
    for (glm::dvec3& p : m.positions) p.z = 0.1 * std::sin(3.0 * p.x + 2.0 * p.y);  // curved: limits off the cage
    for (std::size_t v = 1; v + 1 < m.positions.size(); v += 2) m.positions[v] = m.positions[v + 1];
    return m;
}

TEST(LimitErrorEdges, SharedPerTriangleEqualsTheDefinitionEdgeByEdge) {
    // A large tolerance shows most corners coarse; a small one most of them fine.
    for (double share : {0.05, 0.003}) expect_values_by_definition(octahedron(), 2, share, rgb::LimitErrorCriterion::Samples::AnyNeighbourhood);
    expect_values_by_definition(torus(4, 3), 1, 0.01, rgb::LimitErrorCriterion::Samples::AnyNeighbourhood);
    expect_values_by_definition(grid_with_tied_corners(), 1, 0.01, rgb::LimitErrorCriterion::Samples::AnyNeighbourhood);
}

TEST(LimitErrorEdges, BesideTheEdgeEqualsTheDefinitionEdgeByEdge) {
    for (const TestMesh& m : {octahedron(), grid_with_tied_corners()})
        expect_values_by_definition(m, 1, 0.01, rgb::LimitErrorCriterion::Samples::BesideTheEdge);
}

}  // namespace
}  // namespace rgbtest
