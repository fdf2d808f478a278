// docs/loop-face-varying.md checked against Far for every UV interpolation option on the meshes of
// uv_meshes.cpp, levels 0-4, to 1e-12 of the UV bounding-box diagonal: the UV topology of every level
// (§1), the rule of every value one level finer (§2, §3), the closed forms from every level and the
// limits (§4).
#include <algorithm>
#include <map>
#include <set>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "uv_meshes.h"
#include "uv_rules.h"

namespace osdoracle {
namespace {

constexpr int finest = 4;

const std::map<UvInterpolation, std::string> option_names{
    {UvInterpolation::none, "none"},
    {UvInterpolation::corners_only, "corners_only"},
    {UvInterpolation::corners_plus1, "corners_plus1"},
    {UvInterpolation::corners_plus2, "corners_plus2"},
    {UvInterpolation::boundaries, "boundaries"},
    {UvInterpolation::all, "all"}};

const std::map<UvKind, std::string> kind_names{{UvKind::linear, "linear"},     {UvKind::matching, "matching"},
                                               {UvKind::crease, "crease"},     {UvKind::corner, "corner"},
                                               {UvKind::semi_sharp, "semi_sharp"}};

// Every case under every option.
std::vector<UvCase> cases_and_options() {
    std::vector<UvCase> all;
    for (const UvCase& c : uv_cases())
        for (const auto& [option, name] : option_names) {
            UvCase with_option = c;
            with_option.name += "_" + name;
            with_option.input.uv->interpolation = option;
            all.push_back(with_option);
        }
    return all;
}

double uv_diagonal(const UvChannel& uv) {
    glm::dvec2 lo = uv.values.front(), hi = uv.values.front();
    for (const glm::dvec2& p : uv.values) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return glm::distance(lo, hi);
}

// Far's refinement of one case, our UV topology and tags of every level, and Far's UVs by our value ids.
struct RefinedUv {
    explicit RefinedUv(const FarInput& in)
        : input(in),
          far(refine_uniform(in, finest)),
          tags(tags_per_level(in, far)),
          topology(uv_topology_per_level(in, far)),
          tolerance(1e-12 * uv_diagonal(*in.uv)) {
        for (int k = 0; k <= finest; ++k) {
            std::vector<glm::dvec2> uv(topology[k].value_vertex.size());
            for (std::size_t t = 0; t < far.levels[k].triangles.size(); ++t)
                for (int c = 0; c < 3; ++c) uv[topology[k].corner_value[t][c]] = far.levels[k].uv[t][c];
            uv_of_value.push_back(uv);
            values.push_back(classify_uv_values(in, far.levels[k], tags[k], topology[k], uv));
        }
    }
    int descendant(int k, int value, int j) const {
        for (int i = 0; i < j; ++i) value = topology[k + i].value_child[value];
        return value;
    }

    FarInput input;
    FarRefinement far;
    std::vector<LevelTags> tags;
    std::vector<UvTopology> topology;
    double tolerance;
    std::vector<std::vector<glm::dvec2>> uv_of_value;
    std::vector<std::vector<UvValue>> values;
};

class UvClosedForms : public testing::TestWithParam<UvCase> {};

// Our values are Far's values: the same corners share a value, at every level.
TEST_P(UvClosedForms, UvTopologyOfEveryLevelIsFars) {
    const RefinedUv r(GetParam().input);
    for (int k = 0; k <= finest; ++k) {
        std::map<int, int> ours_to_far, far_to_ours;
        for (std::size_t t = 0; t < r.far.levels[k].triangles.size(); ++t)
            for (int c = 0; c < 3; ++c) {
                const int ours = r.topology[k].corner_value[t][c], far = r.far.levels[k].uv_value_index[t][c];
                EXPECT_EQ(ours_to_far.emplace(ours, far).first->second, far) << "level " << k << " triangle " << t;
                EXPECT_EQ(far_to_ours.emplace(far, ours).first->second, ours) << "level " << k << " triangle " << t;
            }
    }
}

TEST_P(UvClosedForms, EveryValueOneLevelFinerFollowsItsRule) {
    const RefinedUv r(GetParam().input);
    for (int k = 0; k < finest; ++k) {
        const std::vector<glm::dvec2> finer = uv_one_level_finer(r.input, r.far.levels[k], r.tags[k], r.topology[k],
                                                                 r.values[k], r.topology[k + 1]);
        for (std::size_t v = 0; v < finer.size(); ++v) {
            const UvValueOrigin& o = r.topology[k + 1].value_origin[v];
            EXPECT_LE(glm::distance(finer[v], r.uv_of_value[k + 1][v]), r.tolerance)
                << "level " << k + 1 << " value " << v << " from "
                << (o.on_edge ? "edge " + std::to_string(o.a) + "-" + std::to_string(o.b)
                              : kind_names.at(r.values[k][o.parent_value].kind) + " value " + std::to_string(o.parent_value));
        }
    }
}

TEST_P(UvClosedForms, ClosedFormFromEveryLevel) {
    const RefinedUv r(GetParam().input);
    for (int a = 0; a < finest; ++a)
        for (std::size_t v = 0; v < r.values[a].size(); ++v)
            for (int j = 1; a + j <= finest; ++j)
                EXPECT_LE(glm::distance(uv_closed_form(r.values[a][v], j),
                                        r.uv_of_value[a + j][r.descendant(a, static_cast<int>(v), j)]),
                          r.tolerance)
                    << kind_names.at(r.values[a][v].kind) << " value " << v << " of level " << a << ", j = " << j;
}

// What LimitFaceVarying computes for a UV crease value: the crease limit with the weights written as
// float literals in Far (1.0f/6.0f and 2.0f/3.0f), so only float-accurate even in double precision.
glm::dvec2 far_crease_limit(const UvValue& v) {
    return static_cast<double>(2.0f / 3.0f) * v.uv + static_cast<double>(1.0f / 6.0f) * (v.end0 + v.end1);
}

// The exact limit from any level equals Far's LimitFaceVarying, except at UV creases, where Far uses
// float weights (checked against that formula instead), and at values that follow a geometric dart,
// where Far uses the smooth mask (docs/loop-creases.md §6; skipped).
TEST_P(UvClosedForms, LimitFromEveryLevelEqualsFarsLimitFaceVarying) {
    const RefinedUv r(GetParam().input);
    std::vector<glm::dvec2> far_limit(r.values[finest].size());
    for (std::size_t t = 0; t < r.far.levels[finest].triangles.size(); ++t)
        for (int c = 0; c < 3; ++c) far_limit[r.topology[finest].corner_value[t][c]] = r.far.limit_uv[t][c];
    for (int a = 0; a <= finest; ++a)
        for (std::size_t v = 0; v < r.values[a].size(); ++v) {
            if (!far_limit_is_exact(r.values[a][v])) continue;
            const int last = r.descendant(a, static_cast<int>(v), finest - a);
            const UvValue& at_finest = r.values[finest][last];
            const glm::dvec2 exact = uv_limit(r.values[a][v]);
            if (at_finest.kind == UvKind::crease) {
                EXPECT_LE(glm::distance(far_crease_limit(at_finest), far_limit[last]), r.tolerance);
                EXPECT_LE(glm::distance(exact, uv_limit(at_finest)), r.tolerance);
                EXPECT_LE(glm::distance(exact, far_limit[last]), 1e-7 * glm::length(exact)) << "float weights";
            } else {
                EXPECT_LE(glm::distance(exact, far_limit[last]), r.tolerance)
                    << kind_names.at(r.values[a][v].kind) << " value " << v << " of level " << a;
            }
        }
}

INSTANTIATE_TEST_SUITE_P(UvMeshes, UvClosedForms, testing::ValuesIn(cases_and_options()),
                         [](const testing::TestParamInfo<UvCase>& info) { return info.param.name; });

// The cases must put values of every kind in every situation the note distinguishes.
TEST(UvCases, CoverEveryKindOfValueUnderEveryOption) {
    std::set<std::string> seen;
    for (const UvCase& c : cases_and_options()) {
        const RefinedUv r(c.input);
        const std::string option = option_names.at(c.input.uv->interpolation);
        for (int k = 0; k < 2; ++k) {
            std::map<int, int> values_at_vertex;
            for (int vertex : r.topology[k].value_vertex) ++values_at_vertex[vertex];
            for (std::size_t v = 0; v < r.values[k].size(); ++v) {
                const int vertex = r.topology[k].value_vertex[v];
                const bool boundary = gather_neighbourhood(r.far.levels[k], r.tags[k], vertex).boundary;
                seen.insert(option + " " + kind_names.at(r.values[k][v].kind) + (boundary ? " boundary " : " interior ") +
                            std::to_string(std::min(values_at_vertex[vertex], 3)));
            }
        }
    }
    for (const char* expected : {
             "none crease interior 1",           "none crease interior 2",           "none crease interior 3",
             "none crease boundary 2",           "none matching boundary 1",         "none corner interior 2",
             "none semi_sharp interior 2",       "corners_only crease interior 1",   "corners_only crease interior 3",
             "corners_only corner interior 2",   "corners_only corner boundary 1",   "corners_only corner boundary 2",
             "corners_plus1 crease interior 1",  "corners_plus1 corner interior 3",  "corners_plus1 crease interior 2",
             "corners_plus1 semi_sharp interior 2", "corners_plus2 corner interior 1", "corners_plus2 corner interior 2",
             "boundaries corner boundary 1",     "boundaries corner interior 2",     "boundaries matching interior 1",
             "all linear interior 1",            "all linear boundary 2"})
        EXPECT_TRUE(seen.contains(expected)) << expected;
}

}  // namespace
}  // namespace osdoracle
