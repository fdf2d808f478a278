#include "rgb/lod/view_lod.h"

#include "rgb/lod/refine.h"
#include "rgb/mesh/operators.h"
#include "rgb/values/loop_geometry.h"

namespace rgb {

ViewLod::ViewLod(Mesh& mesh, const ViewLodSettings& settings, const ScreenView& view) : mesh_(mesh), settings_(settings) {
    set_view(view);
}

// The sweep goes on from where it is: restarting it at the first face on every new camera would, while
// the camera keeps moving, visit the same faces every frame and never the rest.
void ViewLod::restart() {
    unchanged_visits_ = 0;
    converged_ = false;
}

void ViewLod::set_view(const ScreenView& view) {
    criterion_ = std::make_unique<ScreenCriterion>(mesh_.shared_base(), view);
    restart();
}

void ViewLod::set_settings(const ViewLodSettings& settings) {
    settings_ = settings;
    restart();
}

double ViewLod::edge_value(HalfedgeId h) const {
    const VertexId a = mesh_.from_vertex(h), b = mesh_.to_vertex(h);
    const int level = mesh_.edge_type(h).level;
    return criterion_->value(control_point(mesh_, a, level), control_point(mesh_, b, level),
                             midpoint(mesh_.base(), mesh_.address(a), mesh_.address(b)));
}

std::optional<double> ViewLod::parent_value(VertexId v) const {
    // v is removable, so the halves of its parent edge are edges of the mesh: the ends are neighbours.
    const BaseMesh& base = mesh_.base();
    const PointStencil s = parent_stencil(base, mesh_.address(v));
    const SurfacePoint ends[2] = {canonical(base, s.ends[0]), canonical(base, s.ends[1])};
    VertexId found[2];
    const HalfedgeId start = mesh_.vertex_halfedge(v);
    HalfedgeId h = start;
    do {
        const VertexId w = mesh_.to_vertex(h);
        const SurfacePoint p = canonical(base, mesh_.address(w));
        for (int i = 0; i < 2; ++i)
            if (p == ends[i]) found[i] = w;
        // On the boundary the last neighbour is reached only as the end of the previous halfedge.
        const HalfedgeId next = mesh_.ccw_rotated(h);
        if (!next.valid()) {
            const VertexId last = mesh_.opposite_vertex(h);
            const SurfacePoint q = canonical(base, mesh_.address(last));
            for (int i = 0; i < 2; ++i)
                if (q == ends[i]) found[i] = last;
        }
        h = next;
    } while (h.valid() && h != start);
    if (!found[0].valid() || !found[1].valid()) return std::nullopt;
    const int level = mesh_.level(v) - 1;
    return criterion_->value(control_point(mesh_, found[0], level), control_point(mesh_, found[1], level), mesh_.address(v));
}

bool ViewLod::visit(FaceId f) {
    const double split_above = settings_.pixels, remove_below = 0.5 * settings_.pixels;
    for (VertexId v : mesh_.face_vertices(f)) {
        if (mesh_.level(v) == 0 || !can_remove_vertex(mesh_, v)) continue;
        const std::optional<double> value = parent_value(v);
        if (value && *value < remove_below) {
            remove_vertex(mesh_, v);
            ++stats_.removals;
            return true;
        }
    }
    if (mesh_.num_faces() >= settings_.max_triangles) return false;
    for (int i = 0; i < 3; ++i) {
        const HalfedgeId h = Mesh::halfedge(f, i);
        const EdgeType t = mesh_.edge_type(h);
        if (t.colour != Colour::Green || t.level >= settings_.max_level) continue;
        if (edge_value(h) > split_above) {
            const std::size_t before = mesh_.num_vertices();
            refine_edge(mesh_, h);
            stats_.splits += mesh_.num_vertices() - before;
            return true;
        }
    }
    return false;
}

bool ViewLod::update(std::chrono::microseconds budget) {
    if (converged_) return true;
    const auto deadline = std::chrono::steady_clock::now() + budget;
    for (;;) {
        // Nothing changed for a whole sweep: with the mesh unchanged, so is every face's verdict.
        if (unchanged_visits_ >= mesh_.face_capacity()) {
            converged_ = true;
            return true;
        }
        if (cursor_ >= mesh_.face_capacity()) cursor_ = 0;
        const FaceId f(cursor_++);
        const bool changed = mesh_.is_live(f) && visit(f);
        unchanged_visits_ = changed ? 0 : unchanged_visits_ + 1;
        // A visit can cost tens of microseconds (a split with its dependencies, or the ring walks and
        // control points of a fine face); the clock costs far less, so it is read after each.
        if (std::chrono::steady_clock::now() >= deadline) return false;
    }
}

}  // namespace rgb
