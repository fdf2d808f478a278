// docs/loop-creases.md checked against Far on every vertex and edge of the tagged meshes, levels 0-4,
// to 1e-12 of the base bounding-box diagonal: the tags and rules of each level (§2), the edge points
// (§1), the closed form of each rule while it lasts (§3), the piecewise closed form of semi-sharp
// vertices from their own level (§4) and the limits (§3, §5).
#include <algorithm>
#include <set>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "crease_closed_form.h"
#include "crease_meshes.h"
#include "support/test_meshes.h"

namespace osdoracle {
namespace {

constexpr int finest = 4;

std::string rule_name(VertexRule r) {
    switch (r) {
    case VertexRule::smooth: return "smooth";
    case VertexRule::dart: return "dart";
    case VertexRule::crease: return "crease";
    case VertexRule::corner: return "corner";
    }
    return "?";
}

// Far's refinement of one case with our own tags of every level, and the neighbourhood of any vertex.
struct Refined {
    explicit Refined(const FarInput& input)
        : far(refine_uniform(input, finest)),
          tags(tags_per_level(input, far)),
          diagonal(rgbtest::bounding_box_diagonal(input.positions)),
          tolerance(1e-12 * diagonal) {
        for (const FarLevel& level : far.levels) around.push_back(triangles_around_vertices(level));
    }
    Neighbourhood at(int k, int v) const { return gather_neighbourhood(far.levels[k], tags[k], v, around[k][v]); }
    int descendant(int k, int v, int j) const {
        for (int i = 0; i < j; ++i) v = far.levels[k + i].vertex_child[v];
        return v;
    }
    int vertices(int k) const { return static_cast<int>(far.levels[k].positions.size()); }
    // Whether vertex v first appears at level k (on an edge of level k-1).
    bool born_at(int k, int v) const { return k == 0 || far.levels[k].origins[v].on_edge; }

    FarRefinement far;
    std::vector<LevelTags> tags;
    double diagonal;
    double tolerance;
    std::vector<std::vector<std::vector<int>>> around;
};

class CreaseClosedForms : public testing::TestWithParam<CreaseCase> {};

TEST_P(CreaseClosedForms, TagsAndRulesOfEveryLevelFollowUniformCreasing) {
    const Refined r(GetParam().input);
    for (int k = 0; k <= finest; ++k) {
        const FarLevel& level = r.far.levels[k];
        ASSERT_EQ(r.tags[k].edge_sharpness.size(), level.edges.size()) << "level " << k;
        for (const FarEdge& e : level.edges)
            EXPECT_EQ(r.tags[k].edge_sharpness.at(edge_key(e.a, e.b)), e.sharpness)
                << "level " << k << " edge " << e.a << "-" << e.b;
        for (int v = 0; v < r.vertices(k); ++v) {
            EXPECT_EQ(r.tags[k].vertex_sharpness[v], level.vertex_sharpness[v]) << "level " << k << " vertex " << v;
            EXPECT_EQ(rule_name(rule_of(r.at(k, v))), rule_name(level.rules[v])) << "level " << k << " vertex " << v;
        }
    }
}

TEST_P(CreaseClosedForms, EdgePointsFollowTheEdgeRuleWhateverTheEndsAre) {
    const Refined r(GetParam().input);
    for (int k = 0; k < finest; ++k) {
        const FarLevel& level = r.far.levels[k];
        std::map<EdgeKey, std::vector<glm::dvec3>> opposite;
        for (const auto& t : level.triangles)
            for (int i = 0; i < 3; ++i) opposite[edge_key(t[i], t[(i + 1) % 3])].push_back(level.positions[t[(i + 2) % 3]]);
        double worst = 0.0;
        for (const FarEdge& e : level.edges) {
            const glm::dvec3 expected = edge_point(level.positions[e.a], level.positions[e.b],
                                                   opposite.at(edge_key(e.a, e.b)),
                                                   r.tags[k].edge_sharpness.at(edge_key(e.a, e.b)));
            worst = std::max(worst, glm::distance(expected, r.far.levels[k + 1].positions[e.child]));
        }
        EXPECT_LE(worst, r.tolerance) << "edges of level " << k;
    }
}

// From every vertex of every level: while its rule lasts, p^{a+j} is the closed form of level-a data.
TEST_P(CreaseClosedForms, ClosedFormOfEachRuleHoldsWhileTheRuleLasts) {
    const Refined r(GetParam().input);
    for (int a = 0; a < finest; ++a)
        for (int v = 0; v < r.vertices(a); ++v) {
            const Neighbourhood n = r.at(a, v);
            const int last = std::min(levels_rule_lasts(n), finest - a);
            for (int j = 1; j <= last; ++j)
                EXPECT_LE(glm::distance(closed_form(n, j), r.far.levels[a + j].positions[r.descendant(a, v, j)]),
                          r.tolerance)
                    << rule_name(rule_of(n)) << " vertex " << v << " of level " << a << ", j = " << j;
        }
}

// From each vertex's own level, across semi-sharp transitions: the piecewise closed form.
TEST_P(CreaseClosedForms, PiecewiseClosedFormFromTheVertexsOwnLevel) {
    const Refined r(GetParam().input);
    for (int level = 0; level < finest; ++level)
        for (int v = 0; v < r.vertices(level); ++v) {
            if (!r.born_at(level, v)) continue;
            const Neighbourhood n = r.at(level, v);
            for (int j = 1; level + j <= finest; ++j)
                EXPECT_LE(glm::distance(piecewise_closed_form(n, j),
                                        r.far.levels[level + j].positions[r.descendant(level, v, j)]),
                          r.tolerance)
                    << "vertex " << v << " of level " << level << ", j = " << j;
        }
}

// Far's Limit uses the rule of the last level; away from darts its masks are the exact limits, so the
// limit computed from any level's data must agree with it.
TEST_P(CreaseClosedForms, LimitFromAnyLevelEqualsFarsLimitAwayFromDarts) {
    const Refined r(GetParam().input);
    for (int a = 0; a <= finest; ++a)
        for (int v = 0; v < r.vertices(a); ++v) {
            const int last = r.descendant(a, v, finest - a);
            ASSERT_EQ(levels_rule_lasts(r.at(finest, last)), rule_lasts_forever);
            if (r.far.levels[finest].rules[last] == VertexRule::dart) continue;
            EXPECT_LE(glm::distance(piecewise_limit(r.at(a, v)), r.far.limit_positions[last]), r.tolerance)
                << "vertex " << v << " of level " << a;
        }
}

// docs/loop-creases.md §5.1: a regular interior crease vertex whose crease edges have sharpness 1 is
// smooth from the next level on, and its limit is 7/12 p + 1/8 (u + w) + 1/24 (the other four
// neighbours), all of this level. Far's Limit is exact there (the vertex is smooth at the last level).
TEST_P(CreaseClosedForms, CreaseEndingAtTheNextLevelHasTheTransitionLimitStencil) {
    const Refined r(GetParam().input);
    int checked = 0;
    for (int a = 0; a < finest; ++a) {
        for (int v = 0; v < r.vertices(a); ++v) {
            const Neighbourhood n = r.at(a, v);
            if (n.boundary || n.ring.size() != 6 || n.vertex_sharpness > 0.0) continue;
            std::vector<int> sharp;
            for (int i = 0; i < 6; ++i)
                if (n.edge_sharpness[i] > 0.0) sharp.push_back(i);
            if (sharp.size() != 2 || n.edge_sharpness[sharp[0]] != 1.0 || n.edge_sharpness[sharp[1]] != 1.0) continue;
            ASSERT_EQ(sharp[1] - sharp[0], 3) << "a regular crease runs straight through its vertex";
            glm::dvec3 others(0.0);
            for (int i = 0; i < 6; ++i)
                if (i != sharp[0] && i != sharp[1]) others += n.ring[i];
            const glm::dvec3 limit =
                7.0 / 12.0 * n.centre + 1.0 / 8.0 * (n.ring[sharp[0]] + n.ring[sharp[1]]) + 1.0 / 24.0 * others;
            EXPECT_LE(glm::distance(limit, r.far.limit_positions[r.descendant(a, v, finest - a)]), r.tolerance)
                << "vertex " << v << " of level " << a;
            ++checked;
        }
    }
    const std::string name = GetParam().name;
    if (name.find("semi_sharp_chain") != std::string::npos || name.find("semi_sharp_meeting") != std::string::npos) {
        EXPECT_GT(checked, 0) << "the semi-sharp cases have such vertices";
    }
}

// A dart's exact limit is the fixed point of its one-ring refinement: the same from every level's
// ring. Far's Limit applies the smooth limit mask to a dart instead, which is not that fixed point:
// its value depends on the level it is applied to.
TEST_P(CreaseClosedForms, DartLimitIsTheFixedPointOfItsRingWhileFarUsesTheSmoothMask) {
    const Refined r(GetParam().input);
    double far_error = 0.0;
    for (int v = 0; v < r.vertices(finest); ++v) {
        if (r.far.levels[finest].rules[v] != VertexRule::dart) continue;
        const Neighbourhood n = r.at(finest, v);
        EXPECT_LE(glm::distance(smooth_limit_mask_result(n), r.far.limit_positions[v]), r.tolerance);
        far_error = std::max(far_error, glm::distance(limit_of_rule(n), r.far.limit_positions[v]));
    }
    for (int a = 0; a < finest; ++a)
        for (int v = 0; v < r.vertices(a); ++v) {
            const Neighbourhood n = r.at(a, v);
            if (rule_of(n) != VertexRule::dart || levels_rule_lasts(n) != rule_lasts_forever) continue;
            EXPECT_LE(glm::distance(limit_of_rule(n), limit_of_rule(r.at(a + 1, r.descendant(a, v, 1)))), r.tolerance)
                << "dart " << v << " of level " << a;
        }
    // Only meaningful where there are darts: Far's value is off by far more than rounding.
    if (far_error > 0.0) {
        EXPECT_GT(far_error, 1e-6 * r.diagonal);
    }
}

// Hand-derived (exact rational arithmetic on D_n, docs/loop-creases.md §4.4): where beta_n is rational
// the dart limit mask is too.
TEST(DartMasks, LimitMasksOfValences3_4_6AreTheExactFixedPoints) {
    const std::vector<std::pair<int, std::vector<double>>> expected{
        {3, {16.0 / 37, 9.0 / 37, 6.0 / 37, 6.0 / 37}},
        {4, {2944.0 / 6385, 217.0 / 1277, 744.0 / 6385, 868.0 / 6385, 744.0 / 6385}},
        {6, {110.0 / 213, 7.0 / 71, 29.0 / 426, 35.0 / 426, 6.0 / 71, 35.0 / 426, 29.0 / 426}}};
    for (const auto& [valence, mask] : expected) {
        const std::vector<double> computed = dart_limit_mask(valence);
        ASSERT_EQ(computed.size(), mask.size());
        for (std::size_t i = 0; i < mask.size(); ++i) EXPECT_NEAR(computed[i], mask[i], 1e-15) << valence << " " << i;
        // j = 0 is the centre alone; many steps converge to the limit mask.
        EXPECT_EQ(dart_mask(valence, 0)[0], 1.0);
        const std::vector<double> far_steps = dart_mask(valence, 80);
        for (std::size_t i = 0; i < mask.size(); ++i) EXPECT_NEAR(far_steps[i], mask[i], 1e-14);
    }
}

INSTANTIATE_TEST_SUITE_P(TaggedMeshes, CreaseClosedForms, testing::ValuesIn(crease_cases()),
                         [](const testing::TestParamInfo<CreaseCase>& info) { return info.param.name; });

// The cases must exercise every rule change of uniform creasing and every kind of edge end, or the
// tests above prove less than they claim.
TEST(CreaseCases, CoverEveryRuleTransitionAndEdgeNeighbourhood) {
    std::set<std::string> seen;
    for (const CreaseCase& c : crease_cases()) {
        const Refined r(c.input);
        for (int k = 0; k < finest; ++k) {
            const FarLevel& level = r.far.levels[k];
            for (int v = 0; v < r.vertices(k); ++v) {
                const std::string from = rule_name(level.rules[v]);
                const std::string to = rule_name(r.far.levels[k + 1].rules[level.vertex_child[v]]);
                seen.insert(from == to ? from : from + "->" + to);
            }
            for (const FarEdge& e : level.edges)
                for (int end : {e.a, e.b})
                    seen.insert((e.sharpness > 0.0 ? "sharp edge at " : "smooth edge at ") + rule_name(level.rules[end]));
        }
    }
    for (const char* expected :
         {"smooth", "dart", "crease", "corner", "crease->dart", "crease->smooth", "dart->smooth", "corner->crease",
          "corner->dart", "corner->smooth", "smooth edge at smooth", "smooth edge at dart", "smooth edge at crease",
          "smooth edge at corner", "sharp edge at dart", "sharp edge at crease", "sharp edge at corner"})
        EXPECT_TRUE(seen.contains(expected)) << expected;
}

}  // namespace
}  // namespace osdoracle
