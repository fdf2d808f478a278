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
#include <chrono>
#include <cstddef>
#include <memory>
#include <optional>

#include "rgb/lod/screen_detail.h"
#include "rgb/mesh/handles.h"
#include "rgb/mesh/mesh.h"

namespace rgb {

struct ViewLodSettings {
    double pixels = 10.0;  // split edges longer than this on screen; remove where shorter than half
    std::size_t max_triangles = 2'000'000;  // no splits beyond this
    int max_level = kMaxLevel;              // edges of this level are never split
};

struct ViewLodStats {
    std::size_t splits = 0, removals = 0;
};

class ViewLod {
public:
    ViewLod(Mesh& mesh, const ViewLodSettings& settings, const ScreenView& view);

    // The next updates judge by this camera and these settings: convergence is judged anew (a whole
    // sweep without change), the sweep going on from where it was.
    void set_view(const ScreenView& view);
    void set_settings(const ViewLodSettings& settings);
    // Works until converged or until `budget` has passed; returns converged().
    bool update(std::chrono::microseconds budget);
    // A whole sweep over the mesh changed nothing for the current view and settings.
    bool converged() const { return converged_; }
    const ViewLodStats& stats() const { return stats_; }

    // The screen value of the green edge of h, and of the edge removable vertex v was inserted on.
    double edge_value(HalfedgeId h) const;
    std::optional<double> parent_value(VertexId v) const;
    const ViewLodSettings& settings() const { return settings_; }

private:
    bool visit(FaceId f);  // returns whether it changed the mesh
    void restart();

    Mesh& mesh_;
    ViewLodSettings settings_;
    std::unique_ptr<ScreenCriterion> criterion_;
    std::uint32_t cursor_ = 0;            // the next face slot of the sweep, wrapping around
    std::size_t unchanged_visits_ = 0;    // face slots visited since the last change or new camera
    bool converged_ = false;
    ViewLodStats stats_;
};

}  // namespace rgb
