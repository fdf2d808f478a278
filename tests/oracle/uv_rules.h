#pragma once
// docs/loop-face-varying.md written as test code: how each UV value of a level is classified (§2),
// what its rule reads, the UV one level finer (§3), the closed forms and limits (§4). Independent of
// src/; the tests compare every number with Far.
#include <vector>

#include <glm/vec2.hpp>

#include "uv_topology.h"
#include "vertex_neighbourhood.h"

namespace osdoracle {

enum class UvKind {
    linear,      // FVAR_LINEAR_ALL: every value keeps its place, every edge is split at its midpoint
    matching,    // UVs continuous around the vertex: the vertex's own rule on the UVs
    crease,      // a smooth UV boundary: the crease rule along the two edges bounding its span
    corner,      // keeps its place
    semi_sharp,  // a corner for `levels_sharp` levels, then a crease
};

struct UvValue {
    UvKind kind = UvKind::matching;
    glm::dvec2 uv{0.0};
    // crease, semi_sharp: the UVs at the far ends of the two edges bounding the value's span, on its side.
    glm::dvec2 end0{0.0}, end1{0.0};
    int levels_sharp = 0;
    // matching: the vertex's neighbourhood with its UVs (z = 0) in place of positions and the geometric tags.
    Neighbourhood uv_ring;
};

// Classifies every value of a level. `uv_of_value` is the UV of each value id of `topology`.
std::vector<UvValue> classify_uv_values(const FarInput& input, const FarLevel& level, const LevelTags& tags,
                                        const UvTopology& topology, const std::vector<glm::dvec2>& uv_of_value);

// §3: the UV of every value one level finer, by the rules, from the values of this level.
std::vector<glm::dvec2> uv_one_level_finer(const FarInput& input, const FarLevel& coarse_level,
                                           const LevelTags& coarse_tags, const UvTopology& coarse,
                                           const std::vector<UvValue>& values, const UvTopology& fine);

// §4: UV of the value's descendant j levels finer, and its limit.
glm::dvec2 uv_closed_form(const UvValue& value, int j);
glm::dvec2 uv_limit(const UvValue& value);
// Whether uv_limit is what LimitFaceVarying computes (it is not at a UV-matching geometric dart, §5).
bool far_limit_is_exact(const UvValue& value);

}  // namespace osdoracle
