#include "rgb/lod/view_lod.h"

#include <algorithm>
#include <cmath>

#include "rgb/lod/refine.h"
#include "rgb/mesh/operators.h"
#include "rgb/values/loop_geometry.h"

namespace rgb {

ViewLod::ViewLod(Mesh& mesh, const ViewLodSettings& settings, const ScreenView& view) : mesh_(mesh), settings_(settings) {
    set_view(view);
    start_pass();
    mesh_.add_observer(this);
}

ViewLod::~ViewLod() { mesh_.remove_observer(this); }

void ViewLod::restart() {
    pass_current_ = false;
    converged_ = false;
}

void ViewLod::start_pass() {
    pass_.clear();
    gathered_ = 0;
    pass_changed_ = false;
    pass_current_ = true;
}

namespace {

// Whether the camera moved enough to see other faces: a camera that only jitters by rounding keeps its
// pass, so that the faces out of view are reached too.
bool moved(const ScreenView& a, const ScreenView& b) {
    double largest = 0.0, change = 0.0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            largest = std::max(largest, std::abs(a.view_projection[c][r]));
            change = std::max(change, std::abs(a.view_projection[c][r] - b.view_projection[c][r]));
        }
    return change > 1e-9 * largest || a.viewport != b.viewport;
}

}  // namespace

// A pass that has done what may be seen starts anew for a camera that moved: what came into view
// comes first, instead of after the faces out of view the old camera left (seconds at millions of
// faces).
void ViewLod::set_view(const ScreenView& view) {
    const bool restart_pass = criterion_ && gathered_ == mesh_.face_capacity() && pass_.only_unseen_left() && moved(view, criterion_->view());
    criterion_ = std::make_unique<ScreenCriterion>(mesh_.shared_base(), view);
    restart();
    if (restart_pass) start_pass();
}

void ViewLod::set_settings(const ViewLodSettings& settings) {
    settings_ = settings;
    restart();
}

void ViewLod::face_added(const Mesh&, FaceId f) {
    ++face_changes_;
    // Slots not gathered yet are gathered when the pass reaches them.
    if (f.idx < gathered_) push(f, 0);
}

void ViewLod::push(FaceId f, int from_level) {
    if (const std::optional<std::size_t> bucket = view_bucket(mesh_, *criterion_, f, from_level)) pass_.push(*bucket, f);
}

void ViewLod::face_removed(const Mesh&, FaceId) { ++face_changes_; }

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

bool ViewLod::visit(FaceId f, int level) {
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
        if (t.colour != Colour::Green || t.level > level || t.level >= settings_.max_level) continue;
        if (edge_value(h) > split_above) {
            const std::size_t before = mesh_.num_vertices();
            refine_edge(mesh_, h);
            stats_.splits += mesh_.num_vertices() - before;
            return true;
        }
    }
    // Its finer edges wait until the pass has done this level's.
    push(f, level + 1);
    return false;
}

bool ViewLod::update(std::chrono::microseconds budget, std::size_t max_face_changes) {
    if (converged_) return true;
    const auto deadline = std::chrono::steady_clock::now() + budget;
    face_changes_ = 0;
    // Gathering a face costs well under a microsecond: the clock is read every so many.
    constexpr std::uint32_t kGatherChunk = 256;
    for (;;) {
        if (gathered_ < mesh_.face_capacity()) {
            const std::uint32_t end = static_cast<std::uint32_t>(std::min<std::size_t>(mesh_.face_capacity(), gathered_ + kGatherChunk));
            for (; gathered_ < end; ++gathered_)
                if (const FaceId f(gathered_); mesh_.is_live(f)) push(f, 0);
        } else if (const std::optional<FaceBuckets::Taken> taken = pass_.pop()) {
            // A slot freed since it was pushed is skipped; one reused is a new face, visited as such.
            if (mesh_.is_live(taken->face) && visit(taken->face, taken->level)) pass_changed_ = true;
        } else if (pass_current_ && !pass_changed_) {
            // Nothing changed in a whole pass for this camera: with the mesh unchanged, so is every verdict.
            converged_ = true;
            return true;
        } else {
            start_pass();
        }
        // A visit can cost tens of microseconds (a split with its dependencies, or the ring walks and
        // control points of a fine face); the clock costs far less, so it is read after each.
        if (face_changes_ >= max_face_changes || std::chrono::steady_clock::now() >= deadline) return false;
    }
}

}  // namespace rgb
