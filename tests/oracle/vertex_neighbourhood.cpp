#include "vertex_neighbourhood.h"

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

namespace osdoracle {

std::vector<std::vector<int>> triangles_around_vertices(const FarLevel& level) {
    std::vector<std::vector<int>> around(level.positions.size());
    for (std::size_t t = 0; t < level.triangles.size(); ++t)
        for (int v : level.triangles[t]) around[v].push_back(static_cast<int>(t));
    return around;
}

Neighbourhood gather_neighbourhood(const FarLevel& level, const LevelTags& tags, int vertex) {
    return gather_neighbourhood(level, tags, vertex, triangles_around_vertices(level)[vertex]);
}

Neighbourhood gather_neighbourhood(const FarLevel& level, const LevelTags& tags, int vertex,
                                   const std::vector<int>& triangles_around) {
    // Each triangle (vertex, x, y), counter-clockwise, links the neighbour x to the neighbour y.
    std::map<int, int> following;
    for (int t : triangles_around) {
        const auto& tri = level.triangles[t];
        const int i = static_cast<int>(std::find(tri.begin(), tri.end(), vertex) - tri.begin());
        following[tri[(i + 1) % 3]] = tri[(i + 2) % 3];
    }
    Neighbourhood n;
    n.centre = level.positions[vertex];
    n.vertex_sharpness = tags.vertex_sharpness[vertex];
    // A boundary fan starts at the neighbour that follows no other one.
    std::set<int> followers;
    for (const auto& link : following) followers.insert(link.second);
    int start = following.begin()->first;
    for (const auto& link : following)
        if (!followers.contains(link.first)) {
            start = link.first;
            n.boundary = true;
            break;
        }
    for (int x = start;;) {
        n.ring_vertices.push_back(x);
        const auto next = following.find(x);
        if (next == following.end() || next->second == start) break;
        x = next->second;
        if (n.ring_vertices.size() > following.size())
            throw std::logic_error("vertex " + std::to_string(vertex) + ": its triangles do not form one fan");
    }
    if (n.ring_vertices.size() != following.size() + (n.boundary ? 1 : 0))
        throw std::logic_error("vertex " + std::to_string(vertex) + ": its triangles do not form one fan");
    for (int x : n.ring_vertices) {
        n.ring.push_back(level.positions[x]);
        n.edge_sharpness.push_back(tags.edge_sharpness.at(edge_key(vertex, x)));
    }
    return n;
}

}  // namespace osdoracle
