#pragma once
// The halfedges of a list of triangles (halfedge 3f + c runs from corner c of face f to the next
// corner) grouped by start vertex, each group sorted by end vertex: pairing a halfedge a -> b with its
// reverse is then a search in b's short group. The base mesh and a restored mesh state pair their
// halfedges this way.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "rgb/mesh/base_mesh.h"
#include "rgb/support/parallel.h"

namespace rgb {

struct OutgoingHalfedges {
    std::vector<std::size_t> start;            // vertex v's entries are [start[v], start[v + 1])
    std::unique_ptr<std::uint64_t[]> entries;  // (end << 32) | halfedge; 3 per face, each written once: nothing zero-fills them first
    // The first directed edge used twice, by start vertex, then end vertex.
    struct Repeat {
        std::uint32_t from, to, face;
    };
    std::optional<Repeat> repeating;

    static std::uint32_t end_vertex(std::uint64_t e) { return static_cast<std::uint32_t>(e >> 32); }
    static std::uint32_t halfedge(std::uint64_t e) { return static_cast<std::uint32_t>(e); }
    std::span<const std::uint64_t> of(std::uint32_t v) const { return {entries.get() + start[v], start[v + 1] - start[v]}; }
};

// The faces must use vertices below nv only.
OutgoingHalfedges outgoing_halfedges(std::span<const Triangle> faces, std::size_t nv);

// pair(h, r) for every halfedge h whose reverse r exists, on several threads (each h once).
template <class Pair>
void pair_halfedges(const OutgoingHalfedges& out, std::size_t nv, const Pair& pair) {
    parallel_for(nv, 1 << 15, [&](std::size_t begin, std::size_t end) {
        for (std::size_t a = begin; a < end; ++a)
            for (std::uint64_t e : out.of(static_cast<std::uint32_t>(a))) {
                const auto back = out.of(OutgoingHalfedges::end_vertex(e));
                const auto it = std::lower_bound(back.begin(), back.end(), std::uint64_t(a) << 32);
                if (it != back.end() && OutgoingHalfedges::end_vertex(*it) == a) pair(OutgoingHalfedges::halfedge(e), OutgoingHalfedges::halfedge(*it));
            }
    });
}

}  // namespace rgb
