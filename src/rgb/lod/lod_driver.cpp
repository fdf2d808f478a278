#include "rgb/lod/lod_driver.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "rgb/lod/canonical_order.h"
#include "rgb/lod/refine.h"
#include "rgb/lod/request_steps.h"
#include "rgb/mesh/operators.h"
#include "rgb/values/loop_geometry.h"

namespace rgb {

// Taken from the back (finest first), each is removable when its turn comes.
std::vector<VertexId> LodDriver::detail_coarsest_first(const Mesh& mesh) {
    std::vector<VertexId> detail;
    for (const std::vector<VertexId>& level : vertices_above_by_level(mesh, 0)) detail.insert(detail.end(), level.begin(), level.end());
    return detail;
}

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
    morton_ = MortonFrame::of_box(lo, hi);
    doomed_ = detail_coarsest_first(mesh_);
    doomed_at_start_ = doomed_.size();
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
    std::fill(vertex_key_.begin(), vertex_key_.begin() + base.num_vertices(), kBaseVertexKey);
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
    if (x.key != y.key) return x.key > y.key;  // the midpoints only for equal keys
    const glm::dvec3 mx = midpoint(x.a, x.b), my = midpoint(y.a, y.b);
    if (mx != my) return comes_before(x.key, mx, y.key, my);
    if ((x.a == y.a && x.b == y.b) || (x.a == y.b && x.b == y.a)) return false;  // one edge queued twice
    return surroundings_come_before(surroundings(x), surroundings(y));
}

// Only for two edges with one midpoint (coincident vertices): rare, so computed from the addresses
// when asked rather than stored.
SplitSurroundings LodDriver::surroundings(const Candidate& c) const {
    const BaseMesh& base = mesh_.base();
    const PointStencil stencil = parent_stencil(base, rgb::midpoint(base, mesh_.address(c.a), mesh_.address(c.b)));
    std::vector<glm::dvec3> opposite;
    for (const SurfacePoint& p : stencil.opposite) opposite.push_back(base_space_position(base, p));
    return split_surroundings(base_space_[c.a.idx], base_space_[c.b.idx], opposite);
}

std::uint64_t LodDriver::edge_key(VertexId a, VertexId b, int level) {
    const std::uint64_t ends_key = std::min(key_of(a), key_of(b));
    if (ends_key == 0) return 0;
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
    const std::uint64_t key = key_from_value(a, b, level, value, ends_key, level_capped);
    if (level_capped) report_.level_cap_bound = true;
    return key;
}

void LodDriver::vertex_added(const Mesh&, VertexId v, VertexId a, VertexId b) {
    ++report_.splits;
    added_vertices_.push_back(v);
    if (v.idx >= vertex_key_.size()) grow_vertex_arrays(std::max<std::size_t>(v.idx + 1, 2 * vertex_key_.size()));
    limit_known_[v.idx] = 0;  // a slot the removals freed holds a new vertex
    base_space_[v.idx] = midpoint(a, b);
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
    // A threshold run of the default value (max-edge over the whole surface) runs to its end too, to
    // a size estimated from the base (room_for_threshold).
    std::size_t faces = 0, vertices = 0;
    // A threshold run that asks for the budget's room (the editor's Automatic LOD) gets it as well.
    const bool to_budget = settings_.threshold <= 0.0 || settings_.room_for_budget;
    const std::size_t expected = to_budget ? settings_.max_triangles : room_for_threshold();
    if (expected > 0) {
        faces = to_budget ? room_for_run() : expected;
        vertices = faces / 2 + mesh_.num_vertices();
    }
    // The mesh before a uniform start, to go back to in one copy should the start prove wrong (rather
    // than by removing its vertices one by one): copied before the table of limits is reserved, whose
    // room the copy would take too (megabytes of fresh pages, a tenth of a budget's engine time).
    const int start_level = uniform_start_to_try();
    if (start_level > 0) before_uniform_start_ = std::make_unique<Mesh>(mesh_);
    key_base_vertices(vertices);
    report_before_start_ = report_;
    // The coarser vertices get their limits cached (finer splits and keys need them): 268k for a
    // budget of 1.5M triangles on a torus, so a quarter of the budget leaves room to spare.
    if (expected > 0) reserve_room(faces, vertices, expected / 4);
    if (start_level > 0) {
        refine_uniform_start(start_level);
        // Undone at once, it went back to the copy, whose table of limits has no room, and the
        // assignment stopped the threads faulting the room in.
        if (uniform_start_failed_ && expected > 0) reserve_room(faces, vertices, expected / 4);
    }
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
    first_band_ = band_;
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

double LodDriver::progress() const {
    if (done_) return 1.0;
    if (!(settings_.threshold > 0.0)) return 0.0;
    const double removals_share = doomed_at_start_ > 0 ? 0.5 : 0.0;
    if (!refining_) return removals_share * (1.0 - static_cast<double>(doomed_.size()) / static_cast<double>(doomed_at_start_));
    // Every wanted split's band is at least the threshold's (value_band grows with the value).
    const std::size_t last = static_cast<std::size_t>(value_band(settings_.threshold));
    if (first_band_ < last) return removals_share;
    const double in_band = band_sorted_ && !band_list_.empty() ? static_cast<double>(band_next_) / static_cast<double>(band_list_.size()) : 0.0;
    const double bands_taken = static_cast<double>(first_band_ - std::max(band_, last)) + in_band;
    // Weights 1, 2, 4, ... over the bands: the share of their sum taken so far.
    const double splits_share = (std::exp2(bands_taken) - 1.0) / (std::exp2(static_cast<double>(first_band_ - last + 1)) - 1.0);
    return removals_share + (1.0 - removals_share) * std::min(splits_share, 1.0);
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
