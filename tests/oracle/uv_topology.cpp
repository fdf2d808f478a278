#include "uv_topology.h"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace osdoracle {
namespace {

std::set<EdgeKey> seams_of(const std::vector<std::array<int, 3>>& triangles,
                           const std::vector<std::array<int, 3>>& corner_value) {
    // The values each triangle has at the smaller and the larger end of each of its edges.
    std::map<EdgeKey, std::vector<std::pair<int, int>>> sides;
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (int i = 0; i < 3; ++i) {
            const int j = (i + 1) % 3;
            const bool ordered = triangles[t][i] < triangles[t][j];
            const int low = corner_value[t][ordered ? i : j], high = corner_value[t][ordered ? j : i];
            sides[edge_key(triangles[t][i], triangles[t][j])].push_back({low, high});
        }
    std::set<EdgeKey> seams;
    for (const auto& [edge, values] : sides)
        if (values.size() == 2 && values[0] != values[1]) seams.insert(edge);
    return seams;
}

// Assigns value ids to keys in order of first use.
class IdMap {
public:
    int id(const std::array<int, 3>& key, int vertex, UvTopology& topology, const UvValueOrigin& origin = {}) {
        const auto [it, added] = ids_.emplace(key, static_cast<int>(topology.value_vertex.size()));
        if (added) {
            topology.value_vertex.push_back(vertex);
            topology.value_origin.push_back(origin);
        }
        return it->second;
    }

private:
    std::map<std::array<int, 3>, int> ids_;
};

// The triangle of the coarse level a fine triangle lies in: the coarse vertices its corners come from.
int parent_triangle(const FarLevel& fine, const std::array<int, 3>& t,
                    const std::map<std::array<int, 3>, int>& coarse_by_vertices) {
    std::vector<int> parents;
    for (int v : t) {
        const VertexOrigin& o = fine.origins[v];
        parents.push_back(o.a);
        if (o.on_edge) parents.push_back(o.b);
    }
    std::sort(parents.begin(), parents.end());
    parents.erase(std::unique(parents.begin(), parents.end()), parents.end());
    if (parents.size() != 3) throw std::logic_error("a refined triangle does not lie in one coarse triangle");
    return coarse_by_vertices.at({parents[0], parents[1], parents[2]});
}

}  // namespace

UvTopology base_uv_topology(const FarInput& input) {
    UvTopology topology;
    IdMap ids;
    for (std::size_t t = 0; t < input.triangles.size(); ++t) {
        std::array<int, 3> values{};
        for (int c = 0; c < 3; ++c) {
            const int v = input.triangles[t][c];
            values[c] = ids.id({v, input.uv->corners[t][c], 0}, v, topology);
        }
        topology.corner_value.push_back(values);
    }
    topology.seams = seams_of(input.triangles, topology.corner_value);
    topology.value_origin.clear();
    return topology;
}

UvTopology finer_uv_topology(UvTopology& coarse, const FarLevel& coarse_level, const FarLevel& fine_level) {
    std::map<std::array<int, 3>, int> coarse_by_vertices;
    for (std::size_t t = 0; t < coarse_level.triangles.size(); ++t) {
        std::array<int, 3> sorted = coarse_level.triangles[t];
        std::sort(sorted.begin(), sorted.end());
        coarse_by_vertices[sorted] = static_cast<int>(t);
    }
    enum Kind { from_value, from_edge };
    UvTopology fine;
    IdMap ids;
    coarse.value_child.assign(coarse.value_vertex.size(), -1);
    for (const auto& t : fine_level.triangles) {
        const int parent = parent_triangle(fine_level, t, coarse_by_vertices);
        const auto& parent_tri = coarse_level.triangles[parent];
        std::array<int, 3> values{};
        for (int c = 0; c < 3; ++c) {
            const VertexOrigin& o = fine_level.origins[t[c]];
            if (!o.on_edge) {
                const int corner = static_cast<int>(std::find(parent_tri.begin(), parent_tri.end(), o.a) - parent_tri.begin());
                const int parent_value = coarse.corner_value[parent][corner];
                values[c] = ids.id({from_value, parent_value, 0}, t[c], fine, {false, parent_value});
                coarse.value_child[parent_value] = values[c];
            } else {
                // One value per side of a seam, else one; the inserted vertex names the edge.
                const int side = coarse.seams.contains(edge_key(o.a, o.b)) ? parent : -1;
                values[c] = ids.id({from_edge, t[c], side}, t[c], fine, {true, -1, o.a, o.b, side});
            }
        }
        fine.corner_value.push_back(values);
    }
    fine.seams = seams_of(fine_level.triangles, fine.corner_value);
    return fine;
}

std::vector<UvTopology> uv_topology_per_level(const FarInput& input, const FarRefinement& refinement) {
    std::vector<UvTopology> levels{base_uv_topology(input)};
    for (std::size_t k = 1; k < refinement.levels.size(); ++k)
        levels.push_back(finer_uv_topology(levels.back(), refinement.levels[k - 1], refinement.levels[k]));
    return levels;
}

}  // namespace osdoracle
