// The LOD driver's uniform start (speed machinery beside the canonical order, canonical_order.h): a run
// with every split wanted begins with the uniform levels its budget will surely hold, made by
// refine_uniform in one pass at about a third of the cost per split of the ordinary way, and checked
// against the order afterwards (the result is the same, or the run starts again the ordinary way).
// Measured: the budget engine 1.13-1.18x `level 3` per output triangle on the torus with it
// (docs/benchmarks.md).
#include "rgb/lod/lod_driver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>

#include "rgb/lod/refine.h"
#include "rgb/mesh/base_mesh.h"
#include "rgb/mesh/operators.h"
#include "rgb/support/parallel.h"
#include "rgb/values/loop_geometry.h"
#include "rgb/values/loop_split.h"

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

// The triangles the ordinary run makes of a face with edges `edge` long on average before it comes
// down to splits of value `lowest` (each level halves the edges and quarters the triangles).
double LodDriver::triangles_down_to(double edge, double lowest) {
    return edge > lowest ? std::exp2(2.0 * std::ceil(std::log2(edge / lowest))) : 1.0;
}

// Each base face's mean edge length, and the shortest edge of the base.
std::vector<double> LodDriver::base_mean_edges(double& shortest) const {
    const BaseMesh& base = mesh_.base();
    shortest = std::numeric_limits<double>::infinity();
    std::vector<double> mean_edge(base.num_faces());
    for (std::uint32_t f = 0; f < base.num_faces(); ++f) {
        const Triangle& t = base.face(f);
        double sum = 0.0;
        for (int i = 0; i < 3; ++i) {
            const double length = glm::distance(base.position(t[i]), base.position(t[(i + 1) % 3]));
            shortest = std::min(shortest, length);
            sum += length;
        }
        mean_edge[f] = sum / 3.0;
    }
    return mean_edge;
}

// The level of the uniform start to try, 0 for none: a budget run's (every split wanted) that has
// not proved wrong already, unless uniform_start_hopeless.
int LodDriver::uniform_start_to_try() const {
    if (!settings_.uniform_start || settings_.threshold > 0.0 || uniform_start_failed_) return 0;
    const int level = uniform_start_level();
    return level == 0 || uniform_start_hopeless(level) ? 0 : level;
}

// Whether the start would surely prove wrong, by an estimate from the base mesh alone (it decides only
// whether to try: the result is the same either way). Its lowest vertex's edge is about the base's
// shortest edge halved at each level below `level`; before the ordinary run comes down to that value,
// a base face whose edges are r times as long is split about log2(r) levels deep, into 4^log2(r)
// triangles. On a mesh of very different triangle sizes (a scan, a part with small details) that
// overfills the budget by far, and the start would only be undone at the budget's end, after a whole
// run on top of it (it was 3.5 times the cost per output triangle of a uniform level there).
bool LodDriver::uniform_start_hopeless(int level) const {
    double shortest = 0.0;
    const std::vector<double> mean_edge = base_mean_edges(shortest);
    const double lowest = std::ldexp(shortest, 1 - level);
    if (!(lowest > 0.0)) return true;
    const double budget = static_cast<double>(settings_.max_triangles);
    double triangles = 0.0;
    for (double edge : mean_edge) {
        triangles += triangles_down_to(edge, lowest);
        if (triangles > budget) return true;
    }
    return false;
}

// Whether the start at `level` would surely prove wrong: the same estimate as
// uniform_start_hopeless, from what the start knows exactly, the edges of its finest level (Loop's
// positions, which smoothing draws in where a region is small or curved) and its lowest vertex's
// band. The ordinary run holds every vertex outranking that one, about 4^d triangles for a face of
// the start whose edges are 2^d times as long on average. Over the corpus of budget_corpus.sh that
// estimate was 0.78-1.28 times the triangles the run held when it passed below the lowest vertex;
// every start that proved wrong had an estimate at least 1.40 times its budget, every one that held
// at most 1.03. Above 1.25 times the budget the start is undone at once (its result would be the
// same; it would prove wrong only at the budget's end, after a whole run on top of it: half the
// engine time of `budget 700000` on the bunny). Only with the default value, whose halving per level
// it assumes.
//
// Judged from the mesh one level short of the start (made, with its limits and keys; `lowest` its
// lowest vertex, none at the base), before the finest level is made, which is three quarters of the
// start's cost: the finest level's vertices split this mesh's edges (split_position, the bits
// refine_uniform gives them), their keys' bands are those of these edges' values, and each face of
// this mesh becomes four. Making the finest level before judging it was about a quarter of the engine
// time of `budget 1500000` on the machined part, whose start is undone (docs/benchmarks.md). Every
// vertex of this mesh has its limit cached (learn_uniform_limits), so split_position only reads.
bool LodDriver::uniform_start_overflows(int level, const std::optional<Candidate>& lowest) const {
    if (!plain_edge_length_) return false;
    if (lowest && lowest->key == 0) return true;
    const int coarser = level - 1;
    const std::size_t faces = mesh_.face_capacity();
    const std::size_t blocks = parallel_blocks(faces, 8192);
    // The finest vertices' least band (a key's band is the least of its own and its ends', so the
    // lowest vertex's is the least of every vertex's own), or none wanted.
    std::vector<std::uint64_t> least_band(blocks, value_band(std::numeric_limits<double>::infinity()));
    std::vector<std::uint8_t> unwanted(blocks, 0);
    parallel_blocks_for(faces, blocks, [&](std::size_t block, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const FaceId f(static_cast<std::uint32_t>(i));
            if (!mesh_.is_live(f)) continue;
            for (int k = 0; k < 3; ++k) {
                const HalfedgeId h = Mesh::halfedge(f, k);
                const double value = plain_edge_length(mesh_.from_vertex(h), mesh_.to_vertex(h), coarser);
                if (!(value > settings_.threshold)) unwanted[block] = 1;
                least_band[block] = std::min(least_band[block], value_band(value));
            }
        }
    });
    if (std::find(unwanted.begin(), unwanted.end(), 1) != unwanted.end()) return true;
    std::uint64_t band = *std::min_element(least_band.begin(), least_band.end());
    if (lowest) band = std::min(band, lowest->key >> 48);
    const double least = std::exp2((static_cast<double>(band) - 32768.0) / 2.0);  // the band's least value
    std::vector<double> triangles(blocks, 0.0);
    parallel_blocks_for(faces, blocks, [&](std::size_t block, std::size_t begin, std::size_t end) {
        // A face's edges' mean length, as a sum of thirds. The finer mesh may list a face's corners
        // from another one, so the sum may differ in its last bit from one taken there, which changes
        // a face's estimate only at an exact power of two: the totals were those of the finer mesh on
        // every mesh of budget_corpus.sh at budgets of 2,000 to 3,000,000.
        auto mean = [](const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& r) {
            return glm::distance(p, q) / 3.0 + glm::distance(q, r) / 3.0 + glm::distance(r, p) / 3.0;
        };
        double sum = 0.0;
        for (std::size_t i = begin; i < end; ++i) {
            const FaceId f(static_cast<std::uint32_t>(i));
            if (!mesh_.is_live(f)) continue;
            glm::dvec3 corner[3], split[3];  // at `level`: the corners' control points, the new vertices on the edges from them
            for (int k = 0; k < 3; ++k) {
                const HalfedgeId h = Mesh::halfedge(f, k);
                corner[k] = known_control_point(mesh_.from_vertex(h), level);
                split[k] = split_position(mesh_, h);
            }
            for (int k = 0; k < 3; ++k) sum += triangles_down_to(mean(corner[k], split[k], split[(k + 2) % 3]), least);
            sum += triangles_down_to(mean(split[0], split[1], split[2]), least);
        }
        triangles[block] = sum;
    });
    double total = 0.0;
    for (double t : triangles) total += t;
    return total > 1.25 * static_cast<double>(settings_.max_triangles);
}

// The uniform levels up to `level` from the mesh as it is (the base, or the levels below made), with
// their limits and their vertices' keys as a split would give them (a key depends on the vertex's
// edge alone), `lowest` the lowest of those vertices so far.
void LodDriver::make_uniform_levels(int level, std::optional<Candidate>& lowest) {
    keys_wait_ = true;
    refine_uniform(mesh_, level);
    keys_wait_ = false;
    if (plain_edge_length_) learn_uniform_limits(level);
    // Level by level (refine_uniform makes them in that order): a vertex's key needs its parents'.
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
}

// Every vertex of the uniform levels up to `level`, through refine_uniform, keyed. The run then goes
// on from that mesh; the result is the same if every one of those vertices is wanted and outranks the
// split where the budget stops (then the ordinary run holds them all, and from there the two make
// the same splits), which split_next checks against the lowest of them. The mesh before it is in
// before_uniform_start_, to go back to.
void LodDriver::refine_uniform_start(int level) {
    std::optional<Candidate> lowest;
    // One level short first, where uniform_start_overflows can judge the whole start (refine_uniform
    // goes level by level: the mesh is the one it would have made on its way).
    make_uniform_levels(level - 1, lowest);
    if (uniform_start_overflows(level, lowest)) {
        undo_uniform_start();
        return;
    }
    make_uniform_levels(level, lowest);
    uniform_lowest_ = lowest;
    if (lowest->key == 0) undo_uniform_start();
}

// The uniform start held a vertex the ordinary run would not have: back to the mesh the run started
// from, copied before the start, with no candidates, no limits known by slot (the copy's table of
// limits holds only what the base had), and the report of before the start, for the ordinary way from
// there. The copy keeps the arrays' room (a vector assigned a shorter one keeps its capacity), but
// not the table of limits' (copied before it was reserved): start_refining reserves it again.
void LodDriver::undo_uniform_start() {
    uniform_start_failed_ = true;
    uniform_lowest_.reset();
    clear_added_faces();
    mesh_ = *before_uniform_start_;
    before_uniform_start_.reset();
    std::fill(limit_known_.begin(), limit_known_.end(), std::uint8_t(0));
    bands_.clear();
    band_list_.clear();
    queue_ = decltype(queue_)(Lower{this});
    band_next_ = 0;
    band_sorted_ = false;
    steps_ = 0;
    report_ = report_before_start_;
}

}  // namespace rgb
