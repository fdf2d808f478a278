#pragma once
// The face-varying (UV) topology of each level as docs/loop-face-varying.md §1 predicts it from the
// base UV indices and the vertex origins: which triangle corners share a value, and which edges are
// seams. Derived here, not read from Far, so that the tests can compare it with Far's.
#include <array>
#include <set>
#include <vector>

#include "crease_tags.h"
#include "osd_far.h"

namespace osdoracle {

// Where a value of level k >= 1 comes from: the child of a value of level k-1, or the vertex inserted
// on the edge {a, b} of level k-1, on the side of `side_triangle` for a seam (-1 for any other edge).
struct UvValueOrigin {
    bool on_edge = false;
    int parent_value = -1;
    int a = -1, b = -1, side_triangle = -1;
};

struct UvTopology {
    std::vector<std::array<int, 3>> corner_value;  // value id of each triangle corner
    std::vector<int> value_vertex;                 // the vertex each value sits on
    std::vector<UvValueOrigin> value_origin;       // empty on level 0
    std::vector<int> value_child;                  // the value's id one level finer; empty on the last level
    std::set<EdgeKey> seams;                       // edges whose two triangles disagree at an end
};

// Level 0: one value per pair (vertex, input UV index).
UvTopology base_uv_topology(const FarInput& input);
// Level k+1: the child of a vertex keeps one value per value of its parent; the vertex inserted on a
// seam gets one value per side, on any other edge one value. Fills coarse.value_child.
UvTopology finer_uv_topology(UvTopology& coarse, const FarLevel& coarse_level, const FarLevel& fine_level);
std::vector<UvTopology> uv_topology_per_level(const FarInput& input, const FarRefinement& refinement);

}  // namespace osdoracle
