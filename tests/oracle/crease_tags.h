#pragma once
// Crease tags at every level, derived from the base tags by our own reading of OpenSubdiv's uniform
// creasing (docs/loop-creases.md §2), not read from Far: the tests compare them with Far's.
#include <map>
#include <utility>
#include <vector>

#include "osd_far.h"

namespace osdoracle {

using EdgeKey = std::pair<int, int>;  // smaller vertex first
EdgeKey edge_key(int a, int b);

struct LevelTags {
    std::map<EdgeKey, double> edge_sharpness;  // every edge of the level
    std::vector<double> vertex_sharpness;
};

bool is_infinite(double sharpness);
// One level of uniform creasing: infinite stays infinite, s > 1 becomes s - 1, the rest becomes 0.
double sharpness_one_level_finer(double sharpness);
// Sdc's rule: a sharp vertex or three or more sharp edges make a corner; two a crease; one a dart.
VertexRule rule_for(double vertex_sharpness, int sharp_edges);

// Level 0: the input's tags, boundary edges infinitely sharp, and with edge-and-corner boundaries
// every vertex with a single face infinitely sharp.
LevelTags base_tags(const FarInput& input);
// Level k+1 from level k: an edge joining the child of vertex a to the vertex inserted on the edge
// {a, b} is half of {a, b} and inherits its sharpness one level finer; edges inside a face are smooth.
LevelTags finer_tags(const LevelTags& coarse, const FarLevel& fine);
std::vector<LevelTags> tags_per_level(const FarInput& input, const FarRefinement& refinement);

}  // namespace osdoracle
