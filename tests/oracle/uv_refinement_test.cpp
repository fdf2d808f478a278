// The core's face-varying UVs (issue 12, rgb/values/uv_evaluator.h) against OpenSubdiv Far, corner by corner,
// on the UV meshes of uv_meshes.cpp (seams across a grid and ending inside it, three and four seams
// meeting, one-triangle islands, seams crossing sharp and semi-sharp rows, a closed mesh cut along a
// crease, both boundary options, UV bow-ties inside and on the boundary) under the four options the core offers: uniform levels 1-4 equal
// Far's levels, every corner of random adaptive meshes equals Far's UV at its vertex's display level,
// requests stay order independent and level 0 gives the input's UVs back bit for bit.
#include <algorithm>
#include <cstdio>
#include <map>
#include <tuple>
#include <numeric>
#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "far_uv_by_identity.h"
#include "random_requests.h"
#include "rgb/lod/refine.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/face_location.h"
#include "rgb/mesh/journal.h"
#include "rgb/values/loop_geometry.h"
#include "rgb/values/mesh_uvs.h"
#include "rgb/values/uv_evaluator.h"
#include "support/same_mesh.h"
#include "uv_meshes.h"
#include "support/set_level.h"

namespace osdoracle {
namespace {

constexpr int kFarLevels = 4;

double worst_uniform = 0.0, worst_adaptive = 0.0;

std::vector<UvCase> cases_and_options() {
    const std::pair<UvInterpolation, const char*> options[] = {{UvInterpolation::none, "none"},
                                                               {UvInterpolation::corners_only, "corners"},
                                                               {UvInterpolation::boundaries, "boundaries"},
                                                               {UvInterpolation::all, "all"}};
    std::vector<UvCase> all, cases = uv_cases(), bow_ties = uv_bow_tie_cases();
    cases.insert(cases.end(), bow_ties.begin(), bow_ties.end());
    for (const UvCase& c : cases)
        for (const auto& [option, name] : options) {
            UvCase with_option = c;
            with_option.name += std::string("_") + name;
            with_option.input.uv->interpolation = option;
            all.push_back(with_option);
        }
    return all;
}

class UvRefinement : public testing::TestWithParam<UvCase> {
protected:
    static void TearDownTestSuite() {
        std::printf("[ far ] largest UV distance to Far: uniform %.3g, adaptive %.3g (the tolerance is 1e-12 of each "
                    "case's UV bounding-box diagonal)\n",
                    worst_uniform, worst_adaptive);
    }
    const FarInput& input = GetParam().input;
    const FarByIdentity far{input, kFarLevels};
    const FarUvByIdentity far_uv{far};
    const std::shared_ptr<const rgb::BaseMesh> base = tagged_base(input);
    const rgb::UvLayout layout{*base, uv_channel_of(input)};
    rgb::Mesh fresh() const { return rgb::Mesh(base); }

    // Every corner of every face shows Far's UV of its vertex's display level in its base face.
    testing::AssertionResult agrees_with_far_uv(const rgb::Mesh& mesh, const rgbtest::IdentityTracker& ids, double& worst) {
        rgb::UvEvaluator uvs(*base, layout);
        for (rgb::FaceId f : mesh.faces()) {
            const std::uint32_t g = rgb::base_face_of(mesh, f);
            for (int c = 0; c < 3; ++c) {
                const rgb::VertexId v = mesh.face_vertices(f)[static_cast<std::size_t>(c)];
                const int k = rgb::display_level(mesh, v);
                const glm::dvec2* expected = far_uv.uv(k, ids.identity(v), g);
                if (!expected)
                    return testing::AssertionFailure() << "Far has no UV for vertex " << v.idx << " at level " << k
                                                       << " in base face " << g;
                const double error = glm::distance(rgb::displayed_uv(mesh, uvs, f, c), *expected);
                worst = std::max(worst, error);
                if (!(error <= far_uv.tolerance()))
                    return testing::AssertionFailure()
                           << "corner " << c << " of face " << f.idx << " (vertex " << v.idx << ", level " << mesh.level(v)
                           << ", base face " << g << ") at level " << k << " is " << error << " from Far's UV";
            }
        }
        return testing::AssertionSuccess();
    }

    // Level 0: every corner shows the input's UV, bit for bit.
    testing::AssertionResult shows_input_uvs(const rgb::Mesh& mesh) {
        rgb::UvEvaluator uvs(*base, layout);
        for (rgb::FaceId f : mesh.faces())
            for (int c = 0; c < 3; ++c) {
                const rgb::VertexId v = mesh.face_vertices(f)[static_cast<std::size_t>(c)];
                const std::uint32_t g = rgb::base_face_of(mesh, f);
                const auto& t = input.triangles[g];
                const auto i = static_cast<std::size_t>(std::find(t.begin(), t.end(), static_cast<int>(v.idx)) - t.begin());
                if (rgb::displayed_uv(mesh, uvs, f, c) != input.uv->values[static_cast<std::size_t>(input.uv->corners[g][i])])
                    return testing::AssertionFailure() << "corner " << c << " of face " << f.idx;
            }
        return testing::AssertionSuccess();
    }
    // Every face's UVs keyed by its corners' displayed positions (rotated to start at the smallest),
    // which survive any slot order.
    std::map<std::array<double, 9>, std::array<glm::dvec2, 3>> uvs_by_position(const rgb::Mesh& m) { return uvs_by_position(m, layout); }
    static std::map<std::array<double, 9>, std::array<glm::dvec2, 3>> uvs_by_position(const rgb::Mesh& m, const rgb::UvLayout& layout) {
        rgb::UvEvaluator uvs(m.base(), layout);
        std::map<std::array<double, 9>, std::array<glm::dvec2, 3>> by_face;
        for (rgb::FaceId f : m.faces()) {
            std::array<glm::dvec3, 3> p;
            for (int c = 0; c < 3; ++c) p[static_cast<std::size_t>(c)] = rgb::displayed_position(m, m.face_vertices(f)[static_cast<std::size_t>(c)]);
            const auto first = static_cast<int>(std::min_element(p.begin(), p.end(), [](const glm::dvec3& a, const glm::dvec3& b) {
                                                     return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
                                                 }) - p.begin());
            std::array<double, 9> key{};
            std::array<glm::dvec2, 3> uv{};
            for (int i = 0; i < 3; ++i) {
                const int c = (first + i) % 3;
                const glm::dvec3& q = p[static_cast<std::size_t>(c)];
                key[3 * i] = q.x, key[3 * i + 1] = q.y, key[3 * i + 2] = q.z;
                uv[static_cast<std::size_t>(i)] = rgb::displayed_uv(m, uvs, f, c);
            }
            by_face.emplace(key, uv);
        }
        return by_face;
    }
};

TEST_P(UvRefinement, UniformRefinementEqualsFarAtEveryLevel) {
    rgb::Mesh mesh = fresh();
    rgbtest::IdentityTracker ids(mesh, far.oracle());
    ASSERT_TRUE(shows_input_uvs(mesh));
    for (int k = 1; k <= kFarLevels; ++k) {
        rgb::refine_uniform(mesh, k);
        ASSERT_TRUE(agrees_with_far_uv(mesh, ids, worst_uniform)) << "level " << k;
    }
}

TEST_P(UvRefinement, LimitUvsEqualFarsLimitFaceVaryingToItsFloatWeights) {
    // docs/loop-face-varying.md §5: Far's UV crease limit weights are floats (relative error 3e-8);
    // at level 4 no case has a dart left, where Far's limit mask would not be the limit.
    rgb::Mesh mesh = fresh();
    rgbtest::IdentityTracker ids(mesh, far.oracle());
    rgb::refine_uniform(mesh, kFarLevels);
    rgb::UvEvaluator uvs(*base, layout);
    for (rgb::FaceId f : mesh.faces())
        for (int c = 0; c < 3; ++c) {
            const rgb::VertexId v = mesh.face_vertices(f)[static_cast<std::size_t>(c)];
            const glm::dvec2* expected = far_uv.limit_uv(ids.identity(v), rgb::base_face_of(mesh, f));
            ASSERT_NE(expected, nullptr);
            EXPECT_LE(glm::distance(rgb::limit_uv(mesh, uvs, f, c), *expected), 1e-7 * std::max(1.0, glm::length(*expected)))
                << "corner " << c << " of face " << f.idx << " (vertex " << v.idx << ")";
        }
}

TEST_P(UvRefinement, EveryCornerOfRandomAdaptiveMeshesEqualsFarsUvOfItsDisplayLevel) {
    std::mt19937 rng(151);
    for (int trial = 0; trial < 4; ++trial) {
        rgb::Mesh mesh = fresh();
        rgbtest::IdentityTracker ids(mesh, far.oracle());
        for (const rgb::LevelRequest& r : random_requests(input, rng, 6, -1)) {
            rgb::apply_request(mesh, r);
            ASSERT_TRUE(agrees_with_far_uv(mesh, ids, worst_adaptive)) << "trial " << trial;
        }
        rgbtest::set_level(mesh, 0);
        ASSERT_TRUE(shows_input_uvs(mesh)) << "trial " << trial;
    }
}

TEST_P(UvRefinement, RequestsInEveryOrderGiveIdenticalUvs) {
    std::mt19937 rng(152);
    const std::vector<rgb::LevelRequest> requests = random_requests(input, rng, 4, 0);
    std::vector<std::size_t> order(requests.size());
    std::iota(order.begin(), order.end(), 0);
    auto uvs_after = [&](const std::vector<std::size_t>& o) {
        rgb::Mesh m = fresh();
        for (std::size_t i : o) rgb::apply_request(m, requests[i]);
        return uvs_by_position(m);
    };
    const auto first = uvs_after(order);
    while (std::next_permutation(order.begin(), order.end())) ASSERT_TRUE(uvs_after(order) == first);
}

TEST_P(UvRefinement, UndoingRequestsGivesBackIdenticalUvs) {
    std::mt19937 rng(153);
    rgb::Mesh mesh = fresh();
    const std::vector<rgb::LevelRequest> requests = random_requests(input, rng, 6, -1);
    for (std::size_t i = 0; i < 3; ++i) rgb::apply_request(mesh, requests[i]);
    const auto before = uvs_by_position(mesh);
    rgb::Journal journal(mesh);
    journal.start();
    for (std::size_t i = 3; i < requests.size(); ++i) rgb::apply_request(mesh, requests[i]);
    const rgb::JournalRecord record = journal.stop();
    journal.revert(record);
    EXPECT_TRUE(uvs_by_position(mesh) == before);
}

// The input stored differently: vertices and triangles in reverse order, each triangle starting at
// its second corner. Canonical addresses then name other faces and corners; no UV may change a bit.
FarInput restored_differently(const FarInput& in) {
    FarInput out = in;
    const int n = static_cast<int>(in.positions.size());
    auto moved = [&](int v) { return n - 1 - v; };
    std::reverse(out.positions.begin(), out.positions.end());
    out.triangles.clear();
    out.uv->corners.clear();
    for (std::size_t t = in.triangles.size(); t-- > 0;) {
        const auto& tri = in.triangles[t];
        const auto& uv = in.uv->corners[t];
        out.triangles.push_back({moved(tri[1]), moved(tri[2]), moved(tri[0])});
        out.uv->corners.push_back({uv[1], uv[2], uv[0]});
    }
    for (SharpEdge& e : out.creases) e = {moved(e.a), moved(e.b), e.sharpness};
    for (SharpVertex& c : out.corners) c.vertex = moved(c.vertex);
    return out;
}

TEST_P(UvRefinement, AnotherStorageOrderGivesIdenticalUvs) {
    const FarInput other = restored_differently(input);
    const auto other_base = tagged_base(other);
    const rgb::UvLayout other_layout(*other_base, uv_channel_of(other));
    std::mt19937 rng(154);
    rgb::Mesh a = fresh(), b(other_base);
    for (const rgb::LevelRequest& r : random_requests(input, rng, 4, 0)) {
        rgb::apply_request(a, r);
        rgb::apply_request(b, r);
    }
    EXPECT_TRUE(uvs_by_position(a) == uvs_by_position(b, other_layout));
}

INSTANTIATE_TEST_SUITE_P(UvMeshes, UvRefinement, testing::ValuesIn(cases_and_options()),
                         [](const testing::TestParamInfo<UvCase>& info) { return info.param.name; });

}  // namespace
}  // namespace osdoracle

namespace osdoracle {
namespace {

// Deep small regions where seams meet, end, cross a semi-sharp row or an equator crease: every corner
// down to level 6 equals Far's, under none and corners (the options with smooth seam curves).
TEST(UvRefinementDeep, SmallRegionsOnSeamsEqualFarToLevelSix) {
    constexpr int deep = 6;
    double worst = 0.0;
    for (const UvCase& c : uv_cases()) {
        if (c.name != "seam_ending_inside" && c.name != "three_seams_meeting" && c.name != "seam_crossing_semi_sharp_row" &&
            c.name != "equator_seam_on_crease")
            continue;
        for (UvInterpolation option : {UvInterpolation::none, UvInterpolation::corners_only}) {
            FarInput in = c.input;
            in.uv->interpolation = option;
            const FarByIdentity far(in, deep);
            const FarUvByIdentity far_uv(far);
            const auto base = tagged_base(in);
            const rgb::UvLayout layout(*base, uv_channel_of(in));
            rgb::UvEvaluator uvs(*base, layout);
            rgb::Mesh mesh(base);
            rgbtest::IdentityTracker ids(mesh, far.oracle());
            // Around the vertices where seams meet or end: grid (2, 1) and (2, 2), two of the equator's.
            const bool grid = c.name != "equator_seam_on_crease";
            for (int v : grid ? std::vector<int>{7, 12} : std::vector<int>{0, 3}) {
                rgbtest::set_level(mesh, deep, rgb::Sphere{in.positions[static_cast<std::size_t>(v)], 0.15});
                for (rgb::FaceId f : mesh.faces())
                    for (int k = 0; k < 3; ++k) {
                        const rgb::VertexId x = mesh.face_vertices(f)[static_cast<std::size_t>(k)];
                        const glm::dvec2* expected = far_uv.uv(rgb::display_level(mesh, x), ids.identity(x), rgb::base_face_of(mesh, f));
                        ASSERT_NE(expected, nullptr) << c.name;
                        const double error = glm::distance(rgb::displayed_uv(mesh, uvs, f, k), *expected);
                        worst = std::max(worst, error);
                        ASSERT_LE(error, far_uv.tolerance()) << c.name << " around vertex " << v;
                    }
            }
            int finest = 0;
            for (rgb::FaceId f : mesh.faces()) finest = std::max(finest, mesh.level(f));
            EXPECT_EQ(finest, deep) << c.name;
        }
    }
    std::printf("[ far ] largest UV distance to Far at levels up to 6: %.3g\n", worst);
}

}  // namespace
}  // namespace osdoracle
