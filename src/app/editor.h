#pragma once
// The editor's state and behaviour, GL-free: the document, camera, brush, strokes, whole-mesh jobs,
// undo/redo, files and the questions it must ask before discarding work. The window
// (editor_window.cpp) and the panels (editor_panels.cpp) only translate input and draw this state;
// tests drive it directly with the same calls.
//
// Sections: input (mouse, wheel, keys) | brush and strokes | whole-mesh actions | files and
// confirmations | statistics.
#include <chrono>
#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "app/auto_lod.h"
#include "app/brush.h"
#include "app/document.h"
#include "app/input.h"
#include "app/mesh_job.h"
#include "app/stroke_sampler.h"
#include "app/surface_picking.h"
#include "app/view_camera.h"
#include "io/mesh_file.h"

namespace app {

// A question the user must answer before the editor goes on.
enum class Pending { None, DiscardForQuit, DiscardForOpen, Overwrite };

struct DabTiming {
    double last_ms = 0.0;       // engine time (set_level_faces) of the most recent dab
    double last_pick_ms = 0.0;  // picking and footprint of that dab
    std::size_t last_footprint = 0;
    std::size_t dabs = 0;
};

class Editor {
public:
    explicit Editor(glm::ivec2 viewport = {1280, 800});

    Document& document() { return document_; }
    const Document& document() const { return document_; }
    ViewCamera& camera() { return camera_; }
    const ViewCamera& camera() const { return camera_; }
    BrushSettings& brush() { return brush_; }
    AutoLodSettings& auto_lod_settings() { return auto_lod_settings_; }
    rgbio::SaveOptions& save_options() { return save_options_; }
    glm::ivec2 viewport() const { return viewport_; }
    void set_viewport(glm::ivec2 viewport);

    // ---- input ----
    void mouse_moved(glm::vec2 px);
    void mouse_pressed(MouseButton button, Modifiers mods);
    void mouse_released(MouseButton button);
    void scrolled(float steps);
    void key_pressed(Key key, Modifiers mods);
    // Shift held or not, for the stroke under way and the cursor preview.
    void set_modifiers(Modifiers mods) { mods_ = mods; }
    // Advances the running job by a time slice; call once per frame.
    void update(std::chrono::microseconds job_slice = std::chrono::milliseconds(12));

    // ---- brush ----
    bool painting() const { return painting_; }
    // Where the brush would touch the surface now, and its world radius there.
    std::optional<SurfaceHit> cursor_hit();
    double brush_world_radius(const glm::dvec3& at) const;
    BrushMode active_mode() const { return effective_mode(brush_.mode, mods_.shift); }

    // ---- whole-mesh actions ----
    void frame_mesh();
    void reset_view();
    bool undo();
    bool redo();
    void start_flood_fill(int level);
    void start_auto_lod();
    void cancel_job();
    const MeshJob* job() const { return job_.get(); }
    // The level of the face under the cursor becomes the brush's target level.
    bool sample_level_under_cursor();

    // ---- files ----
    // Each returns false and sets an error message when it cannot proceed.
    bool open(const std::string& path);  // no questions asked
    bool save();                         // to the document's path
    bool save_as(const std::string& path);
    // Asks first when there are unsaved changes / the file exists.
    void request_open(const std::string& path);
    void request_save_as(const std::string& path);
    void request_quit();
    // Files dropped on the window: the first is opened as by request_open (the editor holds one mesh).
    void files_dropped(std::span<const std::string> paths);
    Pending pending() const { return pending_; }
    const std::string& pending_path() const { return pending_path_; }
    void answer_pending(bool proceed);
    bool should_quit() const { return quit_; }
    const std::vector<std::string>& recent_files() const { return recent_; }
    const std::string& message() const { return message_; }
    bool message_is_error() const { return message_is_error_; }
    std::string window_title() const;

    // ---- statistics ----
    const DabTiming& dab_timing() const { return timing_; }

private:
    void begin_stroke(glm::vec2 px);
    void continue_stroke(glm::vec2 px);
    void end_stroke();
    void dab(glm::vec2 px);
    // The surface under px, searched near `previous` first when given (spec §3.4).
    std::optional<SurfaceHit> pick(glm::vec2 px, const std::optional<SurfaceHit>& previous, double reach);
    void reseed_after_dab(const std::array<rgb::VertexId, 3>& corners);
    void finish_job();
    void remember_recent(const std::string& path);
    void report(std::string message, bool error);
    bool busy() const { return job_ != nullptr || painting_; }

    Document document_;
    ViewCamera camera_;
    glm::ivec2 viewport_;
    BrushSettings brush_;
    AutoLodSettings auto_lod_settings_;
    rgbio::SaveOptions save_options_;

    glm::vec2 mouse_{0.0f};
    Modifiers mods_;
    enum class Drag { None, Orbit, Pan } drag_ = Drag::None;

    bool painting_ = false;
    bool stroke_changed_ = false;
    StrokeSampler sampler_;
    std::optional<SurfaceHit> last_hit_;
    std::optional<SurfaceHit> cursor_hit_;
    double last_radius_ = 0.0;
    DabTiming timing_;

    std::unique_ptr<MeshJob> job_;

    Pending pending_ = Pending::None;
    std::string pending_path_;
    bool quit_ = false;
    std::vector<std::string> recent_;
    std::string message_;
    bool message_is_error_ = false;
};

}  // namespace app
