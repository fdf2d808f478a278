#pragma once
// Level of detail by a criterion under a triangle budget (spec §3.3), with a canonical result.
//
// Every potential split (a green edge of the hierarchy, named by the vertex it would insert) gets a
// key from the hierarchy alone: the band of its criterion value (half octaves), then the Morton order
// of its base-space midpoint; a key never exceeds the keys of the edge's endpoints, so no vertex
// outranks a vertex it needs. A run means: the minimal RGB mesh holding every wanted vertex whose key
// is above a threshold, with the lowest threshold that keeps the mesh within the budget. So the result
// depends on neither the mesh's history nor its storage, and a budget stops at a whole band or at a
// spatially coherent part of one, never a lace of isolated triangles.
//
// A run starts by removing what the mesh holds above the base (finest first), then splits from the
// highest key down, one split (with the splits it depends on) per step, O(log n) each, so a caller can
// interleave steps with drawing or cancel between them.
//
// canonical_order.h states the order itself, on one screen. This class walks it, in lod_driver.cpp;
// the speed machinery sits beside it, each file saying why it exists: lod_driver_limits.cpp (the
// keys' values), lod_driver_bands.cpp (a sorted list per band instead of one heap),
// lod_driver_room.cpp (the arrays reserved and faulted in ahead) and lod_driver_uniform_start.cpp
// (the uniform levels a budget surely holds, made in one pass).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <queue>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/lod/band_lists.h"
#include "rgb/lod/canonical_order.h"
#include "rgb/mesh/handles.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/observer.h"
#include "rgb/support/prefault.h"
#include "rgb/support/zeroed_vector.h"

namespace rgb {

// What orders the splits: a value of the hierarchy edge (a, b) of the uniform level `level`. It must
// depend on the edge alone (the hierarchy's positions, never the current mesh around it).
using SplitValue = std::function<double(const Mesh&, VertexId a, VertexId b, int level)>;

// The edge's length in the uniform mesh of its level (between its endpoints' Loop positions there).
double edge_length(const Mesh& mesh, VertexId a, VertexId b, int level);

struct LodSettings {
    SplitValue value = edge_length;
    double threshold = 0.0;  // splits whose value is not above it are not wanted
    std::size_t max_triangles = 1'000'000;
    int max_level = kMaxLevel;  // edges of this level are never split
    // A vertex the RGB topology needed (not wanted itself) takes the key of the split that needed
    // it, capped by its endpoints', instead of none; so the edges at it are judged like any other,
    // and a threshold run ends with no unsplit green edge above the threshold: the smallest RGB mesh
    // with that property (criteria that promise something of every face, lod_criteria.h).
    bool split_past_dependencies = false;
    // For a caller that runs to the end rather than step by step between frames: a run with every
    // split wanted (threshold 0) may start with the uniform levels the budget will surely hold,
    // through refine_uniform in one long step (about a third of the cost per split). The result is
    // the same; where the start proves wrong (a vertex of those levels not wanted, or below the
    // split where the budget stops) the run starts again the ordinary way, from a copy of the mesh
    // kept before the start. On a mesh of very different triangle sizes, where an estimate from the
    // base's edges shows it would prove wrong, it is not tried (uniform_start_hopeless); where the
    // same estimate from the start's own finest edges shows it, it is undone at once, judged from the
    // level below before the finest is made (uniform_start_overflows).
    bool uniform_start = false;
    // For a run with a threshold that its budget usually stops first (the editor's automatic LOD,
    // whose threshold is a floor under the budget): room for the budget reserved and faulted in ahead,
    // as a run with every split wanted has it (not the uniform start, whose undo replaces the mesh
    // under its observers). The result is the same; where the threshold stops the run well short of
    // the budget, what was faulted in meanwhile (on another core, until the run ends) is spent in vain.
    bool room_for_budget = false;
};

struct LodReport {
    std::size_t splits = 0, removals = 0;
    bool budget_bound = false;     // a wanted split was left out to stay within the budget
    bool level_cap_bound = false;  // a wanted split was left out at max_level
};

class LodDriver : private MeshObserver {
public:
    LodDriver(Mesh& mesh, LodSettings settings);
    ~LodDriver() override;
    LodDriver(const LodDriver&) = delete;
    LodDriver& operator=(const LodDriver&) = delete;

    // One removal of the old detail, or one wanted split with what it depends on. Returns false once
    // nothing is left to do.
    bool step();
    // Steps until done or `max_steps` steps were made; returns the number made.
    std::size_t run(std::size_t max_steps = static_cast<std::size_t>(-1));
    bool done() const { return done_; }
    // Splits made for wanted vertices (their dependencies included in the report's counts).
    std::size_t steps() const { return steps_; }
    const LodReport& report() const { return report_; }
    // Candidate splits still queued, stale ones included (for progress display).
    std::size_t pending() const;
    // How far a run with a threshold has got, 0 to 1, for a progress bar (a run cannot count its
    // splits ahead): the old detail's removals by count over the first half when there was any, then
    // the bands from the first down to the threshold's, each weighing twice the band before it (a
    // half octave finer holds about twice the splits of a surface), the band under way by the share
    // of its sorted list taken. A budget run (threshold 0) says 0 until done; then 1.
    double progress() const;

private:
    // 16 bytes: the edge's level is not stored, as it is the finer endpoint's (an edge of Σk, k > 0,
    // halves an edge of Σk-1 or joins two of its midpoints, so it has an end of level k).
    struct Candidate {
        std::uint64_t key;
        VertexId a, b;
    };
    struct Lower {
        const LodDriver* driver;
        bool operator()(const Candidate& x, const Candidate& y) const { return driver->outranks(y, x); }
    };
    void vertex_added(const Mesh&, VertexId v, VertexId a, VertexId b) override;
    void vertex_removed(const Mesh&, VertexId) override { ++report_.removals; }
    void face_added(const Mesh&, FaceId f) override;
    void arrays_moving(const Mesh&) override;

    // The vertices above the base, coarsest first.
    static std::vector<VertexId> detail_coarsest_first(const Mesh& mesh);
    bool outranks(const Candidate& x, const Candidate& y) const;
    SplitSurroundings surroundings(const Candidate& c) const;
    // An edge of the mesh, with its level (the finer end's).
    struct Edge {
        VertexId a, b;
        int level;
    };
    std::uint64_t edge_key(VertexId a, VertexId b, int level);
    void edge_keys(std::span<const Edge> edges, std::vector<std::uint64_t>& keys);
    // The key of the edge from its value and the lesser of its ends' keys (not 0). Only reads, so
    // that keys can be computed on several threads; here, so that both callers have it inline.
    std::uint64_t key_from_value(VertexId a, VertexId b, int level, double value, std::uint64_t ends_key, bool& level_capped) const {
        if (!(value > settings_.threshold)) return 0;
        if (level >= settings_.max_level) {
            level_capped = true;
            return 0;
        }
        return split_key(morton_, value, midpoint(a, b), ends_key);
    }
    double plain_edge_length(VertexId a, VertexId b, int level) const;
    glm::dvec3 midpoint(VertexId a, VertexId b) const { return 0.5 * (base_space_[a.idx] + base_space_[b.idx]); }
    std::uint64_t key_of(VertexId v) const { return v.idx < vertex_key_.size() ? vertex_key_[v.idx] : 0; }
    void prepare_limit(VertexId v, int level);
    void cache_limit_cheaply(VertexId v);
    void learn_limit(VertexId v);
    void learn_uniform_limits(int level);
    glm::dvec3 known_control_point(VertexId v, int level) const;
    void key_base_vertices(std::size_t vertices);
    void grow_vertex_arrays(std::size_t size);
    void clear_added_faces();
    void key_new_vertices();
    void push(const Candidate& c);
    void push_new_edges();
    void start_refining();
    std::size_t room_for_run() const;
    std::size_t room_for_threshold() const;
    void stop_room_prefault();
    void reserve_room(std::size_t faces, std::size_t vertices, std::size_t limits);
    void prefault_room(std::size_t faces, std::size_t vertices);
    static double triangles_down_to(double edge, double lowest);
    std::vector<double> base_mean_edges(double& shortest) const;
    int uniform_start_level() const;
    bool uniform_start_hopeless(int level) const;
    int uniform_start_to_try() const;
    bool uniform_start_overflows(int level, const std::optional<Candidate>& lowest) const;
    void make_uniform_levels(int level, std::optional<Candidate>& lowest);
    void refine_uniform_start(int level);
    void undo_uniform_start();
    bool split(const Candidate& c);
    void undo(const std::vector<VertexId>& vertices);
    void sort_band_list();
    std::optional<Candidate> next_candidate();
    bool split_next();

    Mesh& mesh_;
    LodSettings settings_;
    MortonFrame morton_;  // the base-space box, for the keys' Morton codes
    std::vector<VertexId> doomed_;   // old detail, coarsest first (removed from the back)
    ZeroedVector<std::uint64_t> vertex_key_;
    // Base-space positions by midpoint recursion from the base (a canonical value, cheaper than
    // evaluating each vertex's address), for Morton codes and ties.
    ZeroedVector<glm::dvec3> base_space_;
    // Per vertex slot: whether its limit is known to be cached (prepare_limit), so that the check
    // costs a byte rather than a probe of the mesh's limit table; and, with the default value on a
    // mesh without sharp features, the limit itself (limit_), read by slot rather than looked up.
    ZeroedVector<std::uint8_t> limit_known_;
    ZeroedVector<glm::dvec3> limit_;
    bool plain_edge_length_ = false;  // the value is edge_length and every vertex follows Loop's rules
    // Candidates by band (the key's top 16 bits), worked off band by band in key order: a band's list
    // is sorted once when its turn comes (sequential, cheap), and the few candidates a split adds to
    // the band being worked off wait in a small heap merged with that list. So every split comes in
    // the canonical order and a budget stops at exactly the right one, without a heap over everything.
    BandLists<Candidate> bands_;
    ZeroedVector<Candidate> band_list_;  // the current band's, once sorted
    ZeroedVector<Candidate> band_spare_;  // the radix sort's second list (sort_band_list)
    std::size_t band_ = 0, band_next_ = 0;
    bool band_sorted_ = false;
    std::priority_queue<Candidate, std::vector<Candidate>, Lower> queue_;
    const Candidate* splitting_ = nullptr;
    std::vector<FaceId> added_faces_;
    ZeroedVector<std::uint8_t> face_added_;  // per face slot: in added_faces_
    std::vector<VertexId> added_vertices_;
    std::vector<Edge> new_edges_;
    struct Unkeyed {
        VertexId v, a, b;  // a new vertex and its parent edge
    };
    std::vector<Unkeyed> unkeyed_;
    LodReport report_, report_before_start_;
    std::size_t doomed_at_start_ = 0, first_band_ = 0;  // for progress()
    std::size_t steps_ = 0;
    bool refining_ = false, done_ = false;
    // The uniform start: its lowest-ranking vertex (a budget stopping above it proves the start
    // wrong), whether it proved wrong, and whether refine_uniform is running (keys wait for its end).
    std::optional<Candidate> uniform_lowest_;
    bool uniform_start_failed_ = false, keys_wait_ = false;
    std::unique_ptr<Mesh> before_uniform_start_;  // the mesh the start began from, while it may prove wrong
    // A run with every split wanted has the room it reserved, and the mesh's table of limits, faulted
    // in ahead of its writes. Two threads: the room fills front to back, all ranges in step, but the
    // table all over at once (the uniform start's limits), so it cannot wait its turn among them.
    // Last, so that they stop before the arrays go.
    std::unique_ptr<Prefault> prefault_, limit_prefault_;
};

}  // namespace rgb
