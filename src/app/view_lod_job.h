#pragma once
// The editor's view-dependent mode (docs/requests.md "Detail by size, accuracy and view"): a job that never
// ends by itself; every frame it hands the updater (rgb/lod/view_lod.h) the camera as it is now and lets it
// work a time slice, so detail follows the camera while it orbits. Freezing it (cancel) ends the job
// and leaves the current mesh as an ordinary editable state: one undoable step like any job.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "app/mesh_job.h"
#include "rgb/lod/screen_detail.h"
#include "rgb/lod/view_lod.h"

namespace rgb {
class Mesh;
}

namespace app {

class ViewLodJob : public MeshJob {
public:
    // `current_view` is asked once per step for the camera the frame is drawn with. A step stops once
    // its operations have added and removed `max_face_changes` faces, so that the display can take
    // all of them in the same frame and never shows a mesh half changed (Editor::update).
    ViewLodJob(rgb::Mesh& mesh, const rgb::ViewLodSettings& settings, std::function<rgb::ScreenView()> current_view,
               std::size_t max_face_changes = SIZE_MAX);
    ~ViewLodJob() override;
    ViewLodJob(const ViewLodJob&) = delete;
    ViewLodJob& operator=(const ViewLodJob&) = delete;

    // Returns false only once frozen.
    bool step(std::chrono::microseconds slice) override;
    // 1 while the mesh is settled for the current camera, 0 while it catches up.
    float progress() const override;
    bool changed() const override;
    std::string label() const override { return "view-dependent LOD"; }
    // Freezes: the mesh stays as it is.
    void cancel() override { frozen_ = true; }
    // A camera's detail is no script line.
    std::optional<std::string> script() const override { return std::nullopt; }

    bool converged() const { return lod_.converged(); }
    const rgb::ViewLodStats& stats() const { return lod_.stats(); }
    // Takes effect at the next step.
    void set_settings(const rgb::ViewLodSettings& settings) { lod_.set_settings(settings); }
    const rgb::ViewLodSettings& settings() const { return lod_.settings(); }
    // The most faces a step adds and removes (give or take one operation's).
    std::size_t max_face_changes() const { return max_face_changes_; }

private:
    std::function<rgb::ScreenView()> current_view_;
    rgb::ScreenView view_;
    rgb::ViewLod lod_;
    std::size_t max_face_changes_;
    bool frozen_ = false;
};

}  // namespace app
