#pragma once
// Thresholds on edge lengths for criterion tests, chosen where no edge of the hierarchy comes close,
// so that rounding differences between the core and the oracle cannot decide an edge.
#include <glm/geometric.hpp>

#include "support/uniform_loop_oracle.h"

namespace rgbtest {

// The length of the edge (x, y) of Σj in the oracle's mesh of that level (j: the finer end's level).
inline double oracle_edge_length(const UniformLoopOracle& oracle, Identity x, Identity y) {
    const int level = std::max(oracle.level(x), oracle.level(y));
    return glm::distance(oracle.position(level, x), oracle.position(level, y));
}

// A threshold near the given share of the lengths of the edges of Σ0..Σ(cap-1), in a clear gap.
double clear_threshold(const UniformLoopOracle& oracle, int cap, double share);

}  // namespace rgbtest
