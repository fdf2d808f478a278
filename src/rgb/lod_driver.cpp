#include "rgb/lod_driver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "rgb/completed_ring.h"
#include "rgb/half_octave.h"
#include "rgb/loop_geometry.h"
#include "rgb/operators.h"
#include "rgb/parallel.h"
#include "rgb/refine.h"

namespace rgb {

namespace {

constexpr std::uint64_t kBaseKey = std::numeric_limits<std::uint64_t>::max();
constexpr int kBandsPerOctave = 2;
constexpr int kMortonBits = 16;  // per axis

// The low 21 bits of x spread to every third position.
std::uint64_t spread(std::uint64_t x) {
    x &= 0x1fffff;
    x = (x | (x << 32)) & 0x1f00000000ffffull;
    x = (x | (x << 16)) & 0x1f0000ff0000ffull;
    x = (x | (x << 8)) & 0x100f00f00f00f00full;
    x = (x | (x << 4)) & 0x10c30c30c30c30c3ull;
    x = (x | (x << 2)) & 0x1249249249249249ull;
    return x;
}

// The criterion's band: half octaves of the value, biased to 1..65535 (0 means "not wanted").
std::uint64_t band(double value) {
    static_assert(kBandsPerOctave == 2);
    if (!(value > 0.0)) return 1;
    if (!std::isfinite(value)) return 65535;
    return static_cast<std::uint64_t>(std::clamp(half_octave(value), -32767L, 32767L) + 32768L);
}

// The vertices above the base, coarsest first: taken from the back (finest first), each is removable
// when its turn comes.
std::vector<VertexId> detail_coarsest_first(const Mesh& mesh) {
    std::vector<std::vector<VertexId>> by_level(kMaxLevel + 1);
    for (VertexId v : mesh.vertices())
        if (mesh.level(v) > 0) by_level[static_cast<std::size_t>(mesh.level(v))].push_back(v);
    std::vector<VertexId> detail;
    for (const auto& level : by_level) detail.insert(detail.end(), level.begin(), level.end());
    return detail;
}

}  // namespace

double edge_length(const Mesh& mesh, VertexId a, VertexId b, int level) {
    return glm::distance(control_point(mesh, a, level), control_point(mesh, b, level));
}

LodDriver::LodDriver(Mesh& mesh, LodSettings settings)
    : mesh_(mesh), settings_(std::move(settings)), bands_(std::size_t(1) << 16), queue_(Lower{this}) {
    const BaseMesh& base = mesh_.base();
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    for (std::uint32_t v = 0; v < base.num_vertices(); ++v) {
        lo = glm::min(lo, base.position(v));
        hi = glm::max(hi, base.position(v));
    }
    box_lo_ = lo;
    box_scale_ = double((1 << kMortonBits) - 1) / glm::max(hi - lo, glm::dvec3(1e-300));
    doomed_ = detail_coarsest_first(mesh_);
    // The default value reads limits from the driver's own array (edge_key); a criterion of the
    // caller's, or sharp features (whose vertices need no limit for some values), take the general way.
    const auto* value = settings_.value.target<double (*)(const Mesh&, VertexId, VertexId, int)>();
    plain_edge_length_ = value && *value == &edge_length && !base.has_sharp_features();
    face_added_.resize(mesh_.face_capacity());
    mesh_.add_observer(this);
}

LodDriver::~LodDriver() { mesh_.remove_observer(this); }

// Once the old detail is gone, the per-vertex arrays, at the size the run needs (grown later, they
// would copy themselves), and the base vertices' entries.
void LodDriver::key_base_vertices(std::size_t vertices) {
    const BaseMesh& base = mesh_.base();
    grow_vertex_arrays(std::max(vertices, mesh_.vertex_capacity()));
    std::fill(vertex_key_.begin(), vertex_key_.begin() + base.num_vertices(), kBaseKey);
    for (std::uint32_t v = 0; v < base.num_vertices(); ++v) base_space_[v] = base.position(v);
}

// New slots start unkeyed, with no limit known.
void LodDriver::grow_vertex_arrays(std::size_t size) {
    if (size <= vertex_key_.size()) return;
    stop_room_prefault();
    vertex_key_.resize(size);
    base_space_.resize(size);
    limit_known_.resize(size);
    if (plain_edge_length_) limit_.resize(size);
}

bool LodDriver::outranks(const Candidate& x, const Candidate& y) const {
    if (x.key != y.key) return x.key > y.key;
    // Equal keys (an edge whose value is above its endpoints' keys inherits them): the base-space
    // point the split would insert decides, which no storage or history changes.
    const glm::dvec3 px = 0.5 * (base_space_[x.a.idx] + base_space_[x.b.idx]);
    const glm::dvec3 py = 0.5 * (base_space_[y.a.idx] + base_space_[y.b.idx]);
    return std::tie(px.x, px.y, px.z) > std::tie(py.x, py.y, py.z);
}

std::uint64_t LodDriver::edge_key(VertexId a, VertexId b, int level) {
    if (std::min(key_of(a), key_of(b)) == 0) return 0;
    double value = 0.0;
    if (plain_edge_length_) {
        for (VertexId v : {a, b})
            if (level > mesh_.level(v)) learn_limit(v);
        value = plain_edge_length(a, b, level);
    } else {
        prepare_limit(a, level);
        prepare_limit(b, level);
        value = settings_.value(mesh_, a, b, level);
    }
    bool level_capped = false;
    const std::uint64_t key = key_from_value(a, b, level, value, level_capped);
    if (level_capped) report_.level_cap_bound = true;
    return key;
}

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
            if (std::min(key_of(e.a), key_of(e.b)) == 0) continue;
            keys[i] = key_from_value(e.a, e.b, e.level, plain_edge_length(e.a, e.b, e.level), level_capped);
        }
        capped[block] = level_capped;
    });
    if (std::find(capped.begin(), capped.end(), 1) != capped.end()) report_.level_cap_bound = true;
}

// Only reads, so that keys can be computed on several threads.
std::uint64_t LodDriver::key_from_value(VertexId a, VertexId b, int level, double value, bool& level_capped) const {
    if (!(value > settings_.threshold)) return 0;
    if (level >= settings_.max_level) {
        level_capped = true;
        return 0;
    }
    const glm::dvec3 mid = (0.5 * (base_space_[a.idx] + base_space_[b.idx]) - box_lo_) * box_scale_;
    std::uint64_t morton = 0;
    for (int i = 0; i < 3; ++i) morton |= spread(static_cast<std::uint64_t>(std::clamp(mid[i], 0.0, 65535.0))) << (2 - i);
    return std::min((band(value) << 48) | morton, std::min(key_of(a), key_of(b)));
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

glm::dvec3 LodDriver::known_control_point(VertexId v, int level) const {
    if (level <= mesh_.level(v)) return mesh_.insertion_position(v);
    return control_point(mesh_, v, level, limit_[v.idx]);
}

void LodDriver::vertex_added(const Mesh&, VertexId v, VertexId a, VertexId b) {
    ++report_.splits;
    added_vertices_.push_back(v);
    if (v.idx >= vertex_key_.size()) grow_vertex_arrays(std::max<std::size_t>(v.idx + 1, 2 * vertex_key_.size()));
    limit_known_[v.idx] = 0;  // a slot the removals freed holds a new vertex
    base_space_[v.idx] = 0.5 * (base_space_[a.idx] + base_space_[b.idx]);
    unkeyed_.push_back({v, a, b});
    // Within a split the keys wait until it is complete (key_new_vertices), when the mesh around the
    // endpoints can be walked again.
    if (!splitting_ && !keys_wait_) key_new_vertices();
}

// In the order the vertices came, so that each endpoint has its key before its edge's vertex.
void LodDriver::key_new_vertices() {
    for (const Unkeyed& n : unkeyed_) {
        const bool wanted =
            splitting_ && ((splitting_->a == n.a && splitting_->b == n.b) || (splitting_->a == n.b && splitting_->b == n.a));
        std::uint64_t key = wanted ? splitting_->key : edge_key(n.a, n.b, mesh_.level(n.v) - 1);
        if (key == 0 && settings_.split_past_dependencies && splitting_)
            key = std::min({key_of(n.a), key_of(n.b), splitting_->key});
        vertex_key_[n.v.idx] = key;
    }
    unkeyed_.clear();
}

void LodDriver::start_refining() {
    // With every split wanted the run ends at the budget: room for it at once, so that the arrays do
    // not regrow on the way (a split adds a vertex per two triangles, one per triangle on a boundary).
    // The room holds the split that crosses the budget too (undone at once): without it the mesh's
    // arrays doubled for those few faces, a copy of the whole mesh at the last step.
    std::size_t faces = 0, vertices = 0;
    if (settings_.threshold <= 0.0) {
        faces = room_for_run();
        vertices = faces / 2 + mesh_.num_vertices();
        mesh_.reserve(faces, vertices);
        // The coarser vertices get their limits cached (finer splits and keys need them): 268k for
        // a budget of 1.5M triangles on a torus, so a quarter of the budget leaves room to spare.
        mesh_.reserve_limits(settings_.max_triangles / 4);
        // The start's limits then land all over the table: its pages are faulted in on another core
        // meanwhile (33 ms of the main thread's time at 1.5M on a machine with slow page faults).
        limit_prefault_ = std::make_unique<Prefault>(std::vector{mesh_.limit_table()});
        face_added_.resize(std::max(face_added_.size(), faces));
    }
    key_base_vertices(vertices);
    report_before_start_ = report_;
    if (settings_.threshold <= 0.0 && !prefault_) prefault_room(faces, vertices);
    if (settings_.uniform_start && settings_.threshold <= 0.0 && !uniform_start_failed_) refine_uniform_start();
    // The green edges keyed and queued a block at a time, so that the lists stay small and in cache
    // (for the whole mesh they were megabytes of fresh memory: a page fault per 4 KiB written).
    constexpr std::size_t kEdgesPerBlock = 1 << 15;
    std::vector<Edge> edges;
    std::vector<std::uint64_t> keys;
    edges.reserve(kEdgesPerBlock + 3);
    auto key_and_push = [&] {
        edge_keys(edges, keys);
        for (std::size_t i = 0; i < edges.size(); ++i)
            if (keys[i]) push({keys[i], edges[i].a, edges[i].b});
        edges.clear();
    };
    for (FaceId f : mesh_.faces()) {
        for (int i = 0; i < 3; ++i) {
            const HalfedgeId h = Mesh::halfedge(f, i);
            const HalfedgeId o = mesh_.opposite(h);
            if (o.valid() && o < h) continue;  // each edge once
            const EdgeType t = mesh_.edge_type(h);
            if (t.colour == Colour::Green) edges.push_back({mesh_.from_vertex(h), mesh_.to_vertex(h), t.level});
        }
        if (edges.size() >= kEdgesPerBlock) key_and_push();
    }
    key_and_push();
    band_ = bands_.num_bands() - 1;
    while (band_ > 0 && bands_.empty(band_)) --band_;
}

// Face slots a run with every split wanted may fill, from the base: its budget and the split that
// crosses it, or, where the level cap binds first, the uniform mesh at the cap (room reserved and
// faulted in for a budget the run cannot reach would only take memory).
std::size_t LodDriver::room_for_run() const {
    const std::size_t budget = settings_.max_triangles + settings_.max_triangles / 64 + 64;
    if (settings_.max_level >= 16) return budget;
    return std::min(budget, mesh_.num_faces() << (2 * std::max(settings_.max_level, 0)));
}

// The room reserved for the run (face and vertex slots), in the mesh and in the driver's arrays, and
// room for its candidates, faulted in on another core ahead of the splits that fill it. Before the
// uniform start, whose new vertices fill the driver's arrays too (refine_uniform faults in the mesh's
// part as well: the second pass over those pages finds them present).
void LodDriver::prefault_room(std::size_t faces, std::size_t vertices) {
    auto more = [](std::size_t total, std::size_t used) { return total > used ? total - used : 0; };
    std::vector<std::span<std::byte>> room =
        mesh_.room_ahead(more(faces, mesh_.face_capacity()), more(vertices, mesh_.vertex_capacity()));
    const std::size_t used = mesh_.vertex_capacity();
    auto tail = [&room](auto& array, std::size_t from) {
        if (from < array.size()) room.push_back(std::as_writable_bytes(std::span(array).subspan(from)));
    };
    tail(vertex_key_, used);
    tail(base_space_, used);
    tail(limit_known_, used);
    tail(limit_, used);
    tail(face_added_, mesh_.face_capacity());
    // The candidates queued at once: the run queues each green edge its splits make, about 1.7 per
    // triangle it adds (2.4M on the way to 1.5M triangles on a torus), and hands back the chunks of
    // each band it works off; at most 1.0 per triangle of the budget are held at once there (1.51M),
    // so 1.25 leaves room to spare without faulting in pages never used (a third of the pool was).
    // More than that grows the pool, whose new chunks then fault in as they are written.
    room.push_back(bands_.reserve(faces + faces / 4));
    // The longest band: 457k candidates there (30% of the budget); a longer one grows the list.
    for (ZeroedVector<Candidate>* list : {&band_list_, &merged_}) {
        list->reserve(faces * 2 / 5);
        room.push_back(std::as_writable_bytes(std::span(list->data(), list->capacity())));
    }
    prefault_ = std::make_unique<Prefault>(std::move(room));
}

// The threads read the pages they fault in (prefault.h), so they stop before any of the arrays they
// cover moves: a run past the room reserved, which only slows what follows. The room's covers the
// driver's arrays and the mesh's; the table's, only the mesh's table of limits.
void LodDriver::stop_room_prefault() { prefault_.reset(); }

void LodDriver::arrays_moving(const Mesh&) {
    prefault_.reset();
    limit_prefault_.reset();
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

void LodDriver::push(const Candidate& c) {
    const std::size_t band = c.key >> 48;
    if (band_sorted_ && band == band_)
        queue_.push(c);
    else
        bands_.push(band, c);
}

void LodDriver::face_added(const Mesh&, FaceId f) {
    if (keys_wait_) return;  // the uniform start pushes every edge afterwards
    if (f.idx >= face_added_.size()) {
        stop_room_prefault();
        face_added_.resize(std::max<std::size_t>(f.idx + 1, 2 * face_added_.size()));
    }
    if (face_added_[f.idx]) return;  // a slot freed and taken again within the step
    face_added_[f.idx] = 1;
    added_faces_.push_back(f);
}

void LodDriver::clear_added_faces() {
    for (FaceId f : added_faces_) face_added_[f.idx] = 0;
    added_faces_.clear();
}

// The green edges a step created: those inside the faces it added (both sides new) and new boundary
// edges. An edge on the border of the added faces was there before, and queued then. (The order of
// the pushes does not matter: a band is sorted before use, and its heap orders newcomers.)
void LodDriver::push_new_edges() {
    auto added = [&](FaceId f) { return face_added_[f.idx] != 0; };
    for (FaceId f : added_faces_) {
        if (!mesh_.is_live(f)) continue;
        for (int i = 0; i < 3; ++i) {
            const HalfedgeId h = Mesh::halfedge(f, i);
            const HalfedgeId o = mesh_.opposite(h);
            if (o.valid() && (!added(Mesh::face(o)) || o < h)) continue;
            const EdgeType t = mesh_.edge_type(h);
            if (t.colour != Colour::Green) continue;
            const VertexId a = mesh_.from_vertex(h), b = mesh_.to_vertex(h);
            new_edges_.push_back({a, b, t.level});
            for (VertexId v : {a, b}) {
                __builtin_prefetch(&vertex_key_[v.idx]);
                __builtin_prefetch(&base_space_[v.idx]);
                if (!plain_edge_length_ || mesh_.level(v) >= t.level) continue;
                __builtin_prefetch(&limit_[v.idx]);
                if (!limit_known_[v.idx]) mesh_.prefetch_limit(v);  // to be found or cached there
            }
        }
    }
    // Keyed once all are found: the data of their ends, mostly of coarser vertices not touched lately,
    // is on its way meanwhile.
    for (const Edge& e : new_edges_)
        if (const std::uint64_t key = edge_key(e.a, e.b, e.level)) push({key, e.a, e.b});
    new_edges_.clear();
}

// Splits the candidate's edge (with what it depends on) unless it is stale: split already as another's
// dependency.
bool LodDriver::split(const Candidate& c) {
    const HalfedgeId h = mesh_.find_edge(c.a, c.b);
    if (!h.valid()) return false;
    const EdgeType t = mesh_.edge_type(h);
    if (t.colour != Colour::Green) return false;  // its level is the one it was queued with (Candidate)
    clear_added_faces();
    added_vertices_.clear();
    splitting_ = &c;
    refine_edge(mesh_, h);
    key_new_vertices();
    splitting_ = nullptr;
    push_new_edges();
    return true;
}

// Latest first, so that each vertex has no dependents left when its turn comes; removal normalises,
// so the mesh is the one from before those splits exactly.
void LodDriver::undo(const std::vector<VertexId>& vertices) {
    for (auto it = vertices.rbegin(); it != vertices.rend(); ++it)
        if (mesh_.is_live(*it)) remove_with_dependents(mesh_, *it);
}

// The current band's list, highest first. A long list in two halves on two cores, then merged into
// the driver's second list, which the two then swap (equal candidates are the same edge queued
// twice, so the order among them does not matter).
void LodDriver::sort_band_list() {
    auto higher = [this](const Candidate& x, const Candidate& y) { return outranks(x, y); };
    const auto middle = band_list_.begin() + static_cast<std::ptrdiff_t>(band_list_.size() / 2);
    if (parallel_blocks(band_list_.size(), 16384) < 2) {
        std::sort(band_list_.begin(), band_list_.end(), higher);
        return;
    }
    parallel_invoke([&] { std::sort(band_list_.begin(), middle, higher); },
                    [&] { std::sort(middle, band_list_.end(), higher); });
    // Not in place: inplace_merge takes a buffer of half the band from the heap each time, megabytes
    // of fresh pages; the second list was reserved and faulted in with the first.
    if (band_list_.size() > merged_.capacity()) stop_room_prefault();
    merged_.resize(band_list_.size());
    std::merge(band_list_.begin(), middle, middle, band_list_.end(), merged_.begin(), higher);
    band_list_.swap(merged_);
}

// The highest candidate left: the next of the current band's sorted list or of the band's heap of
// newcomers, moving down to the next band when both are empty.
std::optional<LodDriver::Candidate> LodDriver::next_candidate() {
    for (;;) {
        ZeroedVector<Candidate>& band = band_list_;
        if (!band_sorted_) {
            if (bands_.size(band_) > band.capacity()) stop_room_prefault();
            bands_.take(band_, band);
            sort_band_list();
            band_sorted_ = true;
        }
        const bool listed = band_next_ < band.size();
        if (!queue_.empty() && (!listed || outranks(queue_.top(), band[band_next_]))) {
            const Candidate top = queue_.top();
            queue_.pop();
            return top;
        }
        if (listed) {
            // What the next splits read first, while this one is made.
            for (std::size_t ahead = 1; ahead <= 2 && band_next_ + ahead < band.size(); ++ahead) {
                const Candidate& next = band[band_next_ + ahead];
                for (VertexId v : {next.a, next.b}) {
                    mesh_.prefetch(v, ahead == 1);
                    __builtin_prefetch(&vertex_key_[v.idx]);
                    __builtin_prefetch(&base_space_[v.idx]);
                }
            }
            return band[band_next_++];
        }
        band.clear();
        band_next_ = 0;
        band_sorted_ = false;
        do {
            if (band_ == 0) return std::nullopt;
            --band_;
        } while (bands_.empty(band_));
    }
}

bool LodDriver::split_next() {
    while (const std::optional<Candidate> c = next_candidate()) {
        if (!split(*c)) continue;
        if (mesh_.num_faces() > settings_.max_triangles) {
            undo(added_vertices_);
            if (uniform_lowest_ && !outranks(*uniform_lowest_, *c)) {
                undo_uniform_start();
                start_refining();
                continue;
            }
            report_.budget_bound = true;
            return false;
        }
        ++steps_;
        return true;
    }
    return false;
}

std::size_t LodDriver::pending() const {
    std::size_t n = queue_.size() + doomed_.size();
    for (std::size_t b = 0; b <= band_ && b < bands_.num_bands(); ++b) n += bands_.size(b);
    if (band_sorted_) n += band_list_.size() - band_next_;
    return n;
}

bool LodDriver::step() {
    if (done_) return false;
    if (!refining_) {
        if (!doomed_.empty()) {
            const VertexId v = doomed_.back();
            doomed_.pop_back();
            clear_added_faces();
            remove_vertex(mesh_, v);
            return true;
        }
        refining_ = true;
        start_refining();
    }
    if (split_next()) return true;
    done_ = true;
    return false;
}

std::size_t LodDriver::run(std::size_t max_steps) {
    std::size_t n = 0;
    while (n < max_steps && step()) ++n;
    return n;
}

}  // namespace rgb
