#pragma once
// The loader's working form between parsing and the finished LoadedMesh: triangles with the data
// each corner carries, the OBJ face each came from, and for every vertex id the OBJ vertex it is a
// copy of (repairs add copies). Plus the edge incidences the whole-mesh checks are built on.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "rgb/mesh/mesh.h"

namespace rgbio {

struct TriangleSoup {
    std::vector<rgb::Triangle> triangles;
    // Empty when no face has texture coordinates; else per triangle corner (or kNoIndex).
    std::vector<std::array<std::uint32_t, 3>> texcoords;
    std::vector<std::uint32_t> polygons;  // the ObjRecords polygon each triangle came from
    std::vector<std::size_t> lines;       // that polygon's OBJ line
    std::vector<std::uint32_t> vertex_origin;  // per vertex id: the OBJ vertex (index) it stands for

    // Reverses the triangle's winding, carrying its corners' data along.
    void flip(std::size_t t);
    // A new vertex id standing for the same OBJ vertex as `v`.
    std::uint32_t copy_vertex(std::uint32_t v);
};

// One (undirected edge, triangle) incidence; sorting groups the faces of each edge.
struct EdgeUse {
    std::uint32_t a, b;  // a < b
    std::uint32_t triangle;
    auto operator<=>(const EdgeUse&) const = default;
};

// All incidences, sorted by edge, then triangle (so the faces of an edge are in file order).
std::vector<EdgeUse> edge_uses(const std::vector<rgb::Triangle>& triangles);

// Calls f(begin, end) for each run of uses of one edge.
template <class F>
void for_each_edge(const std::vector<EdgeUse>& uses, F&& f) {
    for (std::size_t i = 0; i < uses.size();) {
        std::size_t j = i + 1;
        while (j < uses.size() && uses[j].a == uses[i].a && uses[j].b == uses[i].b) ++j;
        f(i, j);
        i = j;
    }
}

// The corner of t at vertex v (t must contain v).
inline int corner_of(const rgb::Triangle& t, std::uint32_t v) { return t[0] == v ? 0 : t[1] == v ? 1 : 2; }

// Whether t runs along its edge from -> to (rather than to -> from).
inline bool has_directed_edge(const rgb::Triangle& t, std::uint32_t from, std::uint32_t to) {
    return t[(corner_of(t, from) + 1) % 3] == to;
}

}  // namespace rgbio
