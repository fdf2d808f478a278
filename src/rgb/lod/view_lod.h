#pragma once
// View-dependent continuous level of detail (docs/requests.md "Detail by size, accuracy and view"): for the
// current camera, split every green edge whose screen value (screen_detail.h) is above a pixel
// threshold and remove every removable vertex whose parent edge's value is below half of it, a slice
// of work per call, so that detail follows the camera while it moves. Between half the threshold and
// the threshold nothing changes (hysteresis), so the mesh settles: once a whole pass over the mesh
// changes nothing the updater is converged, and a still camera leaves the mesh as it is. Vertices a
// wanted split needs are kept whatever their own value, so outside the frustum and on faces turned
// away only such vertices remain. The mesh is an ordinary RGB mesh throughout (freezing it is just
// stopping).
//
// Work goes in passes. A pass gathers every face (a slice at a time) into buckets by view_bucket
// (view_priority.h) and visits them in that order: faces that may be seen, coarse to fine, largest
// on screen first; the faces a visit makes join the pass in their own buckets, so a pass refines
// level by level. A new camera is judged from the next visit on; once the pass has done the faces
// that may be seen, a new camera starts a new pass at once, so while the camera moves the work stays
// on what comes into view and the rest waits until it stops. The updater is converged after a pass
// begun for the current camera and settings changed nothing.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>

#include "rgb/lod/screen_detail.h"
#include "rgb/lod/view_priority.h"
#include "rgb/mesh/handles.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/observer.h"

namespace rgb {

struct ViewLodSettings {
    double pixels = 10.0;  // split edges longer than this on screen; remove where shorter than half
    std::size_t max_triangles = 2'000'000;  // no splits beyond this
    int max_level = kMaxLevel;              // edges of this level are never split
};

struct ViewLodStats {
    std::size_t splits = 0, removals = 0;
};

class ViewLod : private MeshObserver {
public:
    ViewLod(Mesh& mesh, const ViewLodSettings& settings, const ScreenView& view);
    ~ViewLod() override;
    ViewLod(const ViewLod&) = delete;
    ViewLod& operator=(const ViewLod&) = delete;

    // The next updates judge by this camera and these settings: convergence is judged anew (a whole
    // sweep without change), the sweep going on from where it was.
    void set_view(const ScreenView& view);
    void set_settings(const ViewLodSettings& settings);
    // Works until converged, until `budget` has passed, or until the operations it made have added
    // and removed at least `max_face_changes` faces (so that the display can catch up with all of
    // them in the same frame); returns converged().
    bool update(std::chrono::microseconds budget, std::size_t max_face_changes = SIZE_MAX);
    // A whole sweep over the mesh changed nothing for the current view and settings.
    bool converged() const { return converged_; }
    const ViewLodStats& stats() const { return stats_; }

    // The screen value of the green edge of h, and of the edge removable vertex v was inserted on.
    double edge_value(HalfedgeId h) const;
    std::optional<double> parent_value(VertexId v) const;
    const ViewLodSettings& settings() const { return settings_; }

private:
    // Removes a vertex of f, or splits a green edge of f of `level` or coarser; returns whether it
    // changed the mesh. Without a change, f joins the pass again for its finer green edges.
    bool visit(FaceId f, int level);
    void push(FaceId f, int from_level);
    void restart();
    void start_pass();
    // The faces a visit adds join the pass; every change counts towards update's limit.
    void face_added(const Mesh& mesh, FaceId f) override;
    void face_removed(const Mesh& mesh, FaceId f) override;

    Mesh& mesh_;
    ViewLodSettings settings_;
    std::unique_ptr<ScreenCriterion> criterion_;
    FaceBuckets pass_;
    std::uint32_t gathered_ = 0;   // face slots the pass has put in buckets so far
    bool pass_changed_ = false;    // a visit of this pass changed the mesh
    bool pass_current_ = false;    // the pass began for the current camera and settings
    std::size_t face_changes_ = 0;  // faces added and removed, for update's limit
    bool converged_ = false;
    ViewLodStats stats_;
};

}  // namespace rgb
