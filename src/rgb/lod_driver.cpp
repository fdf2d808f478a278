#include "rgb/lod_driver.h"

#include <algorithm>
#include <glm/geometric.hpp>

#include "rgb/loop_geometry.h"
#include "rgb/mesh.h"
#include "rgb/operators.h"
#include "rgb/refine.h"

namespace rgb {

EdgeExcess edge_length_excess(std::function<double(const glm::dvec3&)> wanted_length) {
    return [wanted = std::move(wanted_length)](const Mesh& mesh, HalfedgeId h) {
        const glm::dvec3 a = displayed_position(mesh, mesh.from_vertex(h));
        const glm::dvec3 b = displayed_position(mesh, mesh.to_vertex(h));
        return glm::length(b - a) - wanted(0.5 * (a + b));
    };
}

EdgeExcess level_excess(std::function<int(const glm::dvec3&)> target_level) {
    return [target = std::move(target_level)](const Mesh& mesh, HalfedgeId h) {
        const glm::dvec3 mid = 0.5 * (displayed_position(mesh, mesh.from_vertex(h)) + displayed_position(mesh, mesh.to_vertex(h)));
        return static_cast<double>(target(mid) - mesh.edge_type(h).level);
    };
}

LodDriver::LodDriver(Mesh& mesh, LodSettings settings) : mesh_(mesh), settings_(std::move(settings)) {
    for (FaceId f : mesh_.faces())
        for (int i = 0; i < 3; ++i) {
            const HalfedgeId h = Mesh::halfedge(f, i);
            const HalfedgeId o = mesh_.opposite(h);
            if (!o.valid() || h < o) push_edge(h);  // each edge once
        }
    for (VertexId v : mesh_.vertices())
        if (mesh_.level(v) > 0) coarsen_queue_.push({vertex_priority(v), v});
    mesh_.add_observer(this);
}

LodDriver::~LodDriver() { mesh_.remove_observer(this); }

void LodDriver::face_added(const Mesh&, FaceId f) { added_.push_back(f); }

void LodDriver::push_edge(HalfedgeId h) {
    const EdgeType t = mesh_.edge_type(h);
    if (t.colour != Colour::Green || t.level >= settings_.max_level) return;
    const double p = settings_.excess(mesh_, h);
    if (p > 0) refine_queue_.push({p, mesh_.from_vertex(h), mesh_.to_vertex(h)});
}

void LodDriver::push_face(FaceId f) {
    // A new face moves its corners (their display level may change), which changes the length of
    // every edge at those corners: re-queue them all, not only the face's own edges.
    for (VertexId v : mesh_.face_vertices(f)) {
        const HalfedgeId start = mesh_.vertex_halfedge(v);
        HalfedgeId h = start;
        do {
            push_edge(h);
            push_edge(Mesh::prev(h));
            h = mesh_.ccw_rotated(h);
        } while (h.valid() && h != start);
        if (mesh_.level(v) > 0) coarsen_queue_.push({vertex_priority(v), v});
    }
}

double LodDriver::vertex_priority(VertexId v) const {
    double worst = -1e300;
    const HalfedgeId start = mesh_.vertex_halfedge(v);
    HalfedgeId h = start;
    do {
        worst = std::max({worst, settings_.excess(mesh_, h), settings_.excess(mesh_, Mesh::prev(h))});
        h = mesh_.ccw_rotated(h);
    } while (h.valid() && h != start);
    return worst;
}

bool LodDriver::try_coarsen() {
    const bool trimming = phase_ == Phase::Trim;
    while (!coarsen_queue_.empty()) {
        const VertexEntry top = coarsen_queue_.top();
        if (trimming ? mesh_.num_faces() <= settings_.max_triangles : top.priority > 0) return false;
        coarsen_queue_.pop();
        if (!mesh_.is_live(top.v) || !can_remove_vertex(mesh_, top.v)) continue;
        // Entries are not updated in place: re-check what the neighbourhood says now.
        if (!trimming && vertex_priority(top.v) > 0) continue;
        remove_vertex(mesh_, top.v);
        return true;
    }
    return false;
}

bool LodDriver::try_refine() {
    while (!refine_queue_.empty() && mesh_.num_faces() < settings_.max_triangles) {
        const EdgeEntry top = refine_queue_.top();
        refine_queue_.pop();
        const HalfedgeId h = mesh_.find_edge(top.a, top.b);
        if (!h.valid() || mesh_.edge_type(h).colour != Colour::Green) continue;
        if (settings_.excess(mesh_, h) <= 0) continue;
        refine_edge(mesh_, top.a, top.b);
        return true;
    }
    return false;
}

bool LodDriver::step() {
    added_.clear();
    bool changed = false;
    while (!changed && phase_ != Phase::Done) {
        switch (phase_) {
            case Phase::Coarsen: changed = try_coarsen(); break;
            case Phase::Refine: changed = try_refine(); break;
            case Phase::Trim: changed = try_coarsen(); break;
            case Phase::Done: break;
        }
        if (changed) break;
        if (phase_ == Phase::Trim) {
            phase_ = Phase::Done;
        } else {
            phase_ = phase_ == Phase::Coarsen ? Phase::Refine : Phase::Trim;
            if (phase_ == Phase::Trim) {
                // Over budget: every removable vertex is a candidate, finest-criterion first.
                coarsen_queue_ = {};
                for (VertexId v : mesh_.vertices())
                    if (mesh_.level(v) > 0) coarsen_queue_.push({vertex_priority(v), v});
            }
        }
    }
    for (FaceId f : added_)
        if (mesh_.is_live(f)) push_face(f);
    if (changed) ++steps_;
    return changed;
}

std::size_t LodDriver::run(std::size_t max_steps) {
    std::size_t n = 0;
    while (n < max_steps && step()) ++n;
    return n;
}

}  // namespace rgb
