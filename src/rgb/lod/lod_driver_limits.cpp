// The values of the LOD driver's keys, fast (speed machinery beside the canonical order,
// canonical_order.h): an edge's length at its level needs its coarser end's limit, which the driver
// keeps by slot (a byte and a read rather than a probe of the mesh's table of limits), completes
// cheaply from the mesh's ring where it can (completed_ring.h), and learns for many edges at once
// before keying them on all cores. The engine's "new edges' keys and queueing" was 227 of 865 ms of a
// budget of 1.5M triangles when profiled (docs/benchmarks.md).
#include "rgb/lod/lod_driver.h"

#include <algorithm>
#include <vector>

#include <glm/geometric.hpp>

#include "rgb/support/parallel.h"
#include "rgb/values/completed_ring.h"
#include "rgb/values/loop_geometry.h"

namespace rgb {

// The keys of many edges of the mesh as it is, into `keys` (a caller's array, reused): one by one
// with a criterion of the caller's (which may keep caches); with the default value, the limits the
// keys need learnt first, then the keys, which then only read, on all cores.
void LodDriver::edge_keys(std::span<const Edge> edges, std::vector<std::uint64_t>& keys) {
    keys.assign(edges.size(), 0);
    if (!plain_edge_length_) {
        for (std::size_t i = 0; i < edges.size(); ++i) keys[i] = edge_key(edges[i].a, edges[i].b, edges[i].level);
        return;
    }
    for (const Edge& e : edges) {
        if (std::min(key_of(e.a), key_of(e.b)) == 0) continue;  // no value needed, as in edge_key
        for (VertexId v : {e.a, e.b})
            if (e.level > mesh_.level(v)) learn_limit(v);
    }
    const std::size_t blocks = parallel_blocks(edges.size(), 8192);
    std::vector<std::uint8_t> capped(blocks, 0);
    parallel_blocks_for(edges.size(), blocks, [&](std::size_t block, std::size_t begin, std::size_t end) {
        bool level_capped = false;
        for (std::size_t i = begin; i < end; ++i) {
            const Edge& e = edges[i];
            const std::uint64_t ends_key = std::min(key_of(e.a), key_of(e.b));
            if (ends_key == 0) continue;
            keys[i] = key_from_value(e.a, e.b, e.level, plain_edge_length(e.a, e.b, e.level), ends_key, level_capped);
        }
        capped[block] = level_capped;
    });
    if (std::find(capped.begin(), capped.end(), 1) != capped.end()) report_.level_cap_bound = true;
}

// edge_length's bits, from the limits kept by slot (known for both ends where the level needs them).
double LodDriver::plain_edge_length(VertexId a, VertexId b, int level) const {
    return glm::distance(known_control_point(a, level), known_control_point(b, level));
}

// A value at `level` needs the limit of an endpoint coarser than that. Most such limits the mesh
// has; of the others, most belong to a vertex with some red halves of coarser triangles still
// around it (the driver split one of its edges before the others), whose ring completes cheaply
// from the mesh (completed_ring.h); the rest take the general way inside the value.
void LodDriver::prepare_limit(VertexId v, int level) {
    if (mesh_.level(v) >= level || limit_known_[v.idx]) return;
    limit_known_[v.idx] = 1;
    cache_limit_cheaply(v);
}

void LodDriver::cache_limit_cheaply(VertexId v) {
    if (mesh_.has_cached_limit(v)) return;
    if (const auto limit = limit_from_completed_ring(mesh_, v)) mesh_.cache_limit(v, *limit);
}

// Keeps the limit of v by slot (plain_edge_length_ only), found as prepare_limit and the value would
// find it, with one probe of the mesh's table of limits.
void LodDriver::learn_limit(VertexId v) {
    if (limit_known_[v.idx]) return;
    limit_known_[v.idx] = 1;
    if (const auto cached = mesh_.cached_limit(v)) {
        limit_[v.idx] = *cached;
    } else if (const auto limit = limit_from_completed_ring(mesh_, v)) {
        mesh_.cache_limit(v, *limit);
        limit_[v.idx] = *limit;
    } else {
        limit_[v.idx] = limit_position(mesh_, v);  // the general way, which caches it
    }
}

glm::dvec3 LodDriver::known_control_point(VertexId v, int level) const {
    if (level <= mesh_.level(v)) return mesh_.insertion_position(v);
    return untagged_control_point(mesh_, v, level, limit_[v.idx]);  // plain_edge_length_: no vertex is tagged
}

}  // namespace rgb
