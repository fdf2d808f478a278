// The LOD driver's uniform start (speed machinery beside the canonical order, canonical_order.h): a run
// with every split wanted begins with the uniform levels its budget will surely hold, made by
// refine_uniform in one pass at about a third of the cost per split of the ordinary way, and checked
// against the order afterwards (the result is the same, or the run starts again the ordinary way).
// Measured: the budget engine 1.13-1.18x `level 3` per output triangle on the torus with it
// (docs/benchmarks.md).
#include "rgb/lod/lod_driver.h"

#include <optional>
#include <vector>

#include "rgb/lod/refine.h"
#include "rgb/mesh/operators.h"
#include "rgb/support/parallel.h"
#include "rgb/values/loop_geometry.h"

namespace rgb {

// Right after refine_uniform, the limits of every vertex up to `level`, coarsest first, each level
// on all cores: a vertex's ring at its own level is then its neighbours, and the coarser ones among
// them have their limits cached already, so that computing a limit only reads the mesh (the table
// is filled between levels, in slot order, which keeps its lines in cache). The keys of the start's
// edges need the coarser ones; the splits after it, the finest.
void LodDriver::learn_uniform_limits(int level) {
    std::vector<std::vector<VertexId>> by_level(static_cast<std::size_t>(level) + 1);
    for (VertexId v : mesh_.vertices())
        if (mesh_.level(v) <= level && !limit_known_[v.idx]) by_level[static_cast<std::size_t>(mesh_.level(v))].push_back(v);
    for (const std::vector<VertexId>& vertices : by_level) {
        parallel_for(vertices.size(), 4096, [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) limit_[vertices[i].idx] = limit_position_uncached(mesh_, vertices[i]);
        });
        for (VertexId v : vertices) {
            limit_known_[v.idx] = 1;
            if (!mesh_.has_cached_limit(v)) mesh_.cache_limit(v, limit_[v.idx]);
        }
    }
}

// The finest uniform level whose triangles fill at most a quarter of the budget: a budget that could
// hold the whole next level holds this one unless its edges' values vary more than about twice
// (longer edges of the next level outranking shorter ones of this), as on a torus with a thick tube.
int LodDriver::uniform_start_level() const {
    const std::size_t faces = mesh_.num_faces(), room = settings_.max_triangles / 4;
    int level = 0;
    while (level + 1 < settings_.max_level && (faces << (2 * (level + 1))) <= room) ++level;
    return level;
}

// Every vertex of the uniform levels, through refine_uniform, with its key as a split would give it
// (a key depends on the vertex's edge alone). The run then goes on from that mesh; the result is the
// same if every one of those vertices is wanted and outranks the split where the budget stops (then
// the ordinary run holds them all, and from there the two make the same splits), which split_next
// checks against the lowest of them.
void LodDriver::refine_uniform_start() {
    const int level = uniform_start_level();
    if (level == 0) return;
    keys_wait_ = true;
    refine_uniform(mesh_, level);
    keys_wait_ = false;
    if (plain_edge_length_) learn_uniform_limits(level);
    // Level by level (refine_uniform makes them in that order): a vertex's key needs its parents'.
    std::optional<Candidate> lowest;
    for (std::size_t first = 0; first < unkeyed_.size();) {
        const int parent_level = mesh_.level(unkeyed_[first].v) - 1;
        std::vector<Edge> parents;
        for (std::size_t i = first; i < unkeyed_.size() && mesh_.level(unkeyed_[i].v) - 1 == parent_level; ++i)
            parents.push_back({unkeyed_[i].a, unkeyed_[i].b, parent_level});
        std::vector<std::uint64_t> keys;
        edge_keys(parents, keys);
        for (std::size_t i = 0; i < keys.size(); ++i) {
            const Unkeyed& n = unkeyed_[first + i];
            vertex_key_[n.v.idx] = keys[i];
            const Candidate c{keys[i], n.a, n.b};
            if (!lowest || outranks(*lowest, c)) lowest = c;
        }
        first += keys.size();
    }
    steps_ += unkeyed_.size();
    unkeyed_.clear();
    uniform_lowest_ = lowest;
    if (lowest->key == 0) undo_uniform_start();
}

// The uniform start held a vertex the ordinary run would not have: back to the mesh the run started
// from (the base: a run removes the old detail first), with no candidates and the report of before
// the start, for the ordinary way from there.
void LodDriver::undo_uniform_start() {
    uniform_start_failed_ = true;
    uniform_lowest_.reset();
    const std::vector<VertexId> detail = detail_coarsest_first(mesh_);
    for (auto it = detail.rbegin(); it != detail.rend(); ++it) remove_vertex(mesh_, *it);
    bands_.clear();
    band_list_.clear();
    queue_ = decltype(queue_)(Lower{this});
    band_next_ = 0;
    band_sorted_ = false;
    clear_added_faces();
    steps_ = 0;
    report_ = report_before_start_;
}

}  // namespace rgb
