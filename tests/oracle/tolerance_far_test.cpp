// The tolerance criterion (rgb/lod/limit_error.h) on tagged meshes: creases, corners, darts, semi-sharp
// features and both boundary options change the Loop rules and so the limit surface; a tolerance
// result must stay within the tolerance of that surface. Checked against the exact limits the tests'
// own closed forms give from Far's neighbourhoods (docs/loop-creases.md §4-§6; exact at darts and
// semi-sharp vertices too, where Far's limit masks are not): every displayed vertex against its own
// limit point, and every green face at its 15 samples (the vertices of Σ(l+2) in it) against theirs.
#include <algorithm>
#include <array>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "crease_closed_form.h"
#include "crease_meshes.h"
#include "crease_tags.h"
#include "far_by_identity.h"
#include "rgb/lod/limit_error.h"
#include "rgb/lod/lod_criteria.h"
#include "rgb/mesh/invariants.h"
#include "rgb/values/loop_geometry.h"
#include "vertex_neighbourhood.h"

namespace osdoracle {
namespace {

constexpr int kTolerancesFarLevels = 5;
constexpr double kShare = 0.02;  // of the base's bounding-box diagonal

double diagonal(const FarInput& input) {
    glm::dvec3 lo = input.positions.front(), hi = lo;
    for (const glm::dvec3& p : input.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return glm::distance(lo, hi);
}

class ToleranceOnTaggedMeshes : public testing::TestWithParam<CreaseCase> {};

TEST_P(ToleranceOnTaggedMeshes, EveryVertexAndEveryGreenFaceSampleIsWithinTheToleranceOfTheTaggedLimit) {
    const FarInput& input = GetParam().input;
    const FarByIdentity far(input, kTolerancesFarLevels);
    const std::vector<LevelTags> tags = tags_per_level(input, far.refinement());
    const rgbtest::UniformLoopOracle& oracle = far.oracle();
    auto exact_limit = [&](rgbtest::Identity id) {
        const int l = oracle.level(id);
        return piecewise_limit(gather_neighbourhood(far.refinement().levels[l], tags[l], far.far_index(l, id)));
    };
    auto middle = [&](rgbtest::Identity a, rgbtest::Identity b) {
        const std::optional<rgbtest::Identity> m = oracle.midpoint(a, b);
        EXPECT_TRUE(m.has_value());
        return m.value_or(a);
    };

    const double tolerance = kShare * diagonal(input);
    rgb::Mesh mesh(tagged_base(input));
    rgbtest::IdentityTracker ids(mesh, oracle);
    rgb::DetailRequest request;
    request.value = rgb::limit_error_value(mesh.shared_base(), tolerance);
    request.threshold = tolerance;
    const rgb::LodReport report = rgb::apply_detail_request(mesh, request);
    ASSERT_FALSE(report.budget_bound || report.level_cap_bound);
    ASSERT_GT(mesh.num_faces(), input.triangles.size());
    ASSERT_LE(mesh.max_vertex_level(), kTolerancesFarLevels - 2);  // so that every sample is a vertex Far has
    EXPECT_TRUE(rgb::check_invariants(mesh).ok());

    double worst = 0.0;
    for (rgb::VertexId v : mesh.vertices()) worst = std::max(worst, glm::distance(rgb::displayed_position(mesh, v), exact_limit(ids.identity(v))));
    EXPECT_LE(worst, tolerance) << "at the displayed vertices";

    std::size_t green_faces = 0;
    worst = 0.0;
    for (rgb::FaceId f : mesh.faces()) {
        if (mesh.colour(f) != rgb::Colour::Green) continue;
        ++green_faces;
        const auto corners = mesh.face_vertices(f);
        std::array<rgbtest::Identity, 3> c{};
        std::array<glm::dvec3, 3> shown{};
        for (std::size_t i = 0; i < 3; ++i) {
            c[i] = ids.identity(corners[i]);
            shown[i] = rgb::displayed_position(mesh, corners[i]);
        }
        // The vertices of Σ(l+2) in the face, with their barycentric coordinates: corners, the edge
        // midpoints of Σ(l+1), the quarter points and the midpoints of the middle triangle's edges.
        struct Sample {
            rgbtest::Identity id;
            glm::dvec3 weights;
        };
        std::vector<Sample> samples;
        const glm::dvec3 unit[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        std::array<rgbtest::Identity, 3> mid{};
        for (std::size_t i = 0; i < 3; ++i) {
            const std::size_t j = (i + 1) % 3;
            mid[i] = middle(c[i], c[j]);
            samples.push_back({c[i], unit[i]});
            samples.push_back({mid[i], 0.5 * (unit[i] + unit[j])});
            samples.push_back({middle(c[i], mid[i]), 0.75 * unit[i] + 0.25 * unit[j]});
            samples.push_back({middle(mid[i], c[j]), 0.25 * unit[i] + 0.75 * unit[j]});
        }
        for (std::size_t i = 0; i < 3; ++i) {
            const std::size_t j = (i + 1) % 3, k = (i + 2) % 3;
            // Between the midpoints of edges i and j: (c_i + 2 c_j + c_k) / 4.
            samples.push_back({middle(mid[i], mid[j]), 0.25 * unit[i] + 0.5 * unit[j] + 0.25 * unit[k]});
        }
        ASSERT_EQ(samples.size(), 15u);
        for (const Sample& s : samples) {
            const glm::dvec3 flat = s.weights.x * shown[0] + s.weights.y * shown[1] + s.weights.z * shown[2];
            worst = std::max(worst, glm::distance(flat, exact_limit(s.id)));
        }
    }
    EXPECT_GT(green_faces, 0u);
    EXPECT_LE(worst, tolerance) << "at the samples of the green faces";
}

INSTANTIATE_TEST_SUITE_P(TaggedMeshes, ToleranceOnTaggedMeshes, testing::ValuesIn(crease_cases()),
                         [](const testing::TestParamInfo<CreaseCase>& info) { return info.param.name; });

}  // namespace
}  // namespace osdoracle
