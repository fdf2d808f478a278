#pragma once
// The level-of-detail driver of spec §3.3: two priority queues (edges too coarse for the criterion,
// vertices finer than needed) and a triangle budget. It runs one operation per step, so a caller can
// interleave it with drawing, show progress, or cancel between steps.
//
// Unlike the plugin's interleaved loop, the work runs in three phases: remove what the criterion
// finds too fine, then refine what it finds too coarse (until the budget), then remove the finest
// vertices while over budget. A removal makes edges longer, so interleaving can split and remove the
// same vertex forever; phases always end.
#include <cstddef>
#include <functional>
#include <queue>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/handles.h"
#include "rgb/observer.h"

namespace rgb {

class Mesh;

// How much an edge is coarser than wanted: positive means "split it", zero or negative means it is
// fine enough. Edges are given by their endpoints (displayed positions available through the mesh).
using EdgeExcess = std::function<double(const Mesh&, HalfedgeId)>;

// Edge length minus the length wanted at the edge's midpoint.
EdgeExcess edge_length_excess(std::function<double(const glm::dvec3&)> wanted_length);
// Target level at the edge's midpoint minus the edge's level.
EdgeExcess level_excess(std::function<int(const glm::dvec3&)> target_level);

struct LodSettings {
    EdgeExcess excess;
    std::size_t max_triangles = 1'000'000;
    int max_level = 8;  // edges of this level are never split
};

class LodDriver : private MeshObserver {
    enum class Phase { Coarsen, Refine, Trim, Done };

public:
    LodDriver(Mesh& mesh, LodSettings settings);
    ~LodDriver() override;
    LodDriver(const LodDriver&) = delete;
    LodDriver& operator=(const LodDriver&) = delete;

    // One split or removal (with what it entails). Returns false once nothing is left to do.
    bool step();
    // Steps until done or `max_steps` steps were made; returns the number made.
    std::size_t run(std::size_t max_steps = static_cast<std::size_t>(-1));
    bool done() const { return phase_ == Phase::Done; }
    std::size_t steps() const { return steps_; }
    // Queue sizes, including stale entries (for progress display).
    std::size_t pending() const { return refine_queue_.size() + coarsen_queue_.size(); }

private:
    struct EdgeEntry {
        double priority;
        VertexId a, b;
        bool operator<(const EdgeEntry& o) const { return priority < o.priority; }  // max-heap
    };
    struct VertexEntry {
        double priority;
        VertexId v;
        bool operator<(const VertexEntry& o) const { return priority > o.priority; }  // min-heap
    };
    void face_added(const Mesh&, FaceId f) override;
    void push_edge(HalfedgeId h);
    void push_face(FaceId f);
    double vertex_priority(VertexId v) const;
    bool try_coarsen();
    bool try_refine();

    Mesh& mesh_;
    LodSettings settings_;
    std::priority_queue<EdgeEntry> refine_queue_;
    std::priority_queue<VertexEntry> coarsen_queue_;
    std::vector<FaceId> added_;
    Phase phase_ = Phase::Coarsen;
    std::size_t steps_ = 0;
};

}  // namespace rgb
