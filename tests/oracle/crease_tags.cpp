#include "crease_tags.h"

#include <algorithm>

namespace osdoracle {
namespace {

// Number of faces on each edge of a level.
std::map<EdgeKey, int> edge_face_counts(const std::vector<std::array<int, 3>>& triangles) {
    std::map<EdgeKey, int> counts;
    for (const auto& t : triangles)
        for (int i = 0; i < 3; ++i) ++counts[edge_key(t[i], t[(i + 1) % 3])];
    return counts;
}

}  // namespace

EdgeKey edge_key(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

bool is_infinite(double sharpness) { return sharpness >= infinite_sharpness; }

double sharpness_one_level_finer(double sharpness) {
    if (is_infinite(sharpness)) return sharpness;
    return sharpness > 1.0 ? sharpness - 1.0 : 0.0;
}

VertexRule rule_for(double vertex_sharpness, int sharp_edges) {
    if (vertex_sharpness > 0.0 || sharp_edges > 2) return VertexRule::corner;
    if (sharp_edges == 2) return VertexRule::crease;
    return sharp_edges == 1 ? VertexRule::dart : VertexRule::smooth;
}

LevelTags base_tags(const FarInput& input) {
    LevelTags tags;
    tags.vertex_sharpness.assign(input.positions.size(), 0.0);
    std::vector<int> faces_at(input.positions.size(), 0);
    for (const auto& t : input.triangles)
        for (int v : t) ++faces_at[v];
    for (const auto& [edge, faces] : edge_face_counts(input.triangles))
        tags.edge_sharpness[edge] = faces == 1 ? infinite_sharpness : 0.0;
    for (const SharpEdge& e : input.creases) {
        double& s = tags.edge_sharpness[edge_key(e.a, e.b)];
        if (!is_infinite(s)) s = e.sharpness;  // a boundary edge stays infinitely sharp
    }
    for (const SharpVertex& c : input.corners) tags.vertex_sharpness[c.vertex] = c.sharpness;
    if (input.boundary == BoundaryInterpolation::edge_and_corner)
        for (std::size_t v = 0; v < faces_at.size(); ++v)
            if (faces_at[v] == 1) tags.vertex_sharpness[v] = infinite_sharpness;
    return tags;
}

LevelTags finer_tags(const LevelTags& coarse, const FarLevel& fine) {
    LevelTags tags;
    for (const VertexOrigin& o : fine.origins)
        tags.vertex_sharpness.push_back(o.on_edge ? 0.0 : sharpness_one_level_finer(coarse.vertex_sharpness[o.a]));
    for (const auto& [edge, faces] : edge_face_counts(fine.triangles)) {
        const VertexOrigin& x = fine.origins[edge.first];
        const VertexOrigin& y = fine.origins[edge.second];
        double sharpness = 0.0;  // both ends inserted on edges: the edge lies inside a coarse face
        if (x.on_edge != y.on_edge) {
            const VertexOrigin& from_edge = x.on_edge ? x : y;
            sharpness = sharpness_one_level_finer(coarse.edge_sharpness.at(edge_key(from_edge.a, from_edge.b)));
        }
        tags.edge_sharpness[edge] = sharpness;
    }
    return tags;
}

std::vector<LevelTags> tags_per_level(const FarInput& input, const FarRefinement& refinement) {
    std::vector<LevelTags> tags{base_tags(input)};
    for (std::size_t k = 1; k < refinement.levels.size(); ++k)
        tags.push_back(finer_tags(tags.back(), refinement.levels[k]));
    return tags;
}

}  // namespace osdoracle
