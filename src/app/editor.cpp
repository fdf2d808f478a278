#include "app/editor.h"

#include <algorithm>
#include <filesystem>
#include <utility>

#include <glm/geometric.hpp>

#include "app/flood_fill.h"
#include "io/obj_error.h"
#include "rgb/mesh.h"

namespace app {
namespace {

constexpr float kDabSpacing = 0.25f;  // of the brush radius: dabs overlap enough to leave no gaps
constexpr std::size_t kMaxRecentFiles = 8;

double milliseconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Editor::Editor(glm::ivec2 viewport) : viewport_(viewport) { frame_mesh(); }

void Editor::set_viewport(glm::ivec2 viewport) { viewport_ = glm::max(viewport, glm::ivec2(1)); }

// ---- input ------------------------------------------------------------------------------------

void Editor::mouse_moved(glm::vec2 px) {
    const glm::vec2 delta = px - mouse_;
    mouse_ = px;
    if (drag_ == Drag::Orbit) camera_.orbit(delta);
    if (drag_ == Drag::Pan) camera_.pan(delta, viewport_);
    if (painting_) continue_stroke(px);
}

void Editor::mouse_pressed(MouseButton button, Modifiers mods) {
    mods_ = mods;
    if (drag_ != Drag::None || painting_) return;
    // Navigation never conflicts with painting: right/middle drag, or Alt with the left button.
    if (button == MouseButton::Right || (button == MouseButton::Left && mods.alt && !mods.shift)) {
        drag_ = Drag::Orbit;
    } else if (button == MouseButton::Middle || (button == MouseButton::Left && mods.alt && mods.shift)) {
        drag_ = Drag::Pan;
    } else if (button == MouseButton::Left && job_ == nullptr && pending_ == Pending::None) {
        begin_stroke(mouse_);
    }
}

void Editor::mouse_released(MouseButton button) {
    if (button == MouseButton::Left && painting_) end_stroke();
    if (button != MouseButton::Left || drag_ != Drag::None) drag_ = Drag::None;
}

void Editor::scrolled(float steps) { camera_.zoom(steps); }

void Editor::key_pressed(Key key, Modifiers mods) {
    mods_ = mods;
    if (mods.ctrl) {
        switch (key) {
            case Key::Z: mods.shift ? redo() : undo(); break;
            case Key::Y: redo(); break;
            case Key::S: save(); break;
            case Key::Q: request_quit(); break;
            default: break;
        }
        return;
    }
    switch (key) {
        case Key::F: frame_mesh(); break;
        case Key::R: reset_view(); break;
        case Key::S: sample_level_under_cursor(); break;
        case Key::LeftBracket: grow_radius(brush_, -1); break;
        case Key::RightBracket: grow_radius(brush_, 1); break;
        case Key::Digit1: brush_.mode = BrushMode::Refine; break;
        case Key::Digit2: brush_.mode = BrushMode::Coarsen; break;
        case Key::Digit3: brush_.mode = BrushMode::SetLevel; break;
        case Key::Escape:
            if (pending_ != Pending::None) answer_pending(false);
            else cancel_job();
            break;
        default: break;
    }
}

void Editor::update(std::chrono::microseconds job_slice) {
    if (job_ && !job_->step(job_slice)) finish_job();
}

// ---- brush and strokes ------------------------------------------------------------------------

double Editor::brush_world_radius(const glm::dvec3& at) const {
    if (brush_.unit == RadiusUnit::World) return brush_.radius_world;
    return brush_.radius_px * camera_.world_per_pixel(camera_.depth_of(at), viewport_);
}

std::optional<SurfaceHit> Editor::cursor_hit() {
    const double reach = cursor_hit_ ? 2.0 * brush_world_radius(cursor_hit_->point) : 0.0;
    cursor_hit_ = pick(mouse_, cursor_hit_, reach);
    return cursor_hit_;
}

std::optional<SurfaceHit> Editor::pick(glm::vec2 px, const std::optional<SurfaceHit>& previous, double reach) {
    const Ray ray = camera_.ray_through(px, viewport_);
    const render::SurfaceGeometry& geometry = document_.geometry();
    // The whole surface only when the cursor left the neighbourhood of the previous hit.
    if (previous && document_.mesh().is_live(previous->face))
        if (auto hit = pick_surface_near(document_.mesh(), geometry, ray, previous->face, previous->point, reach))
            return hit;
    return pick_surface(geometry, ray);
}

void Editor::begin_stroke(glm::vec2 px) {
    painting_ = true;
    stroke_changed_ = false;
    last_hit_.reset();
    document_.begin_edit("brush stroke");
    for (glm::vec2 p : sampler_.begin(px)) dab(p);
}

void Editor::continue_stroke(glm::vec2 px) {
    float spacing_px = kDabSpacing * brush_.radius_px;
    if (brush_.unit == RadiusUnit::World && last_hit_)
        spacing_px = static_cast<float>(kDabSpacing * brush_.radius_world /
                                        camera_.world_per_pixel(camera_.depth_of(last_hit_->point), viewport_));
    for (glm::vec2 p : sampler_.move_to(px, spacing_px)) dab(p);
}

void Editor::end_stroke() {
    painting_ = false;
    document_.end_edit(stroke_changed_);
    last_hit_.reset();
}

void Editor::dab(glm::vec2 px) {
    const auto pick_start = std::chrono::steady_clock::now();
    const double reach =
        last_hit_ ? 2.0 * last_radius_ + kDabSpacing * brush_.radius_px *
                                             camera_.world_per_pixel(camera_.depth_of(last_hit_->point), viewport_)
                  : 0.0;
    const std::optional<SurfaceHit> hit = pick(px, last_hit_, reach);
    if (!hit) {
        last_hit_.reset();
        return;
    }
    rgb::Mesh& mesh = document_.mesh();
    const double radius = brush_world_radius(hit->point);
    const std::vector<rgb::FaceId> footprint =
        faces_in_sphere(mesh, document_.geometry(), hit->face, hit->point, radius);
    timing_.last_pick_ms = milliseconds_since(pick_start);

    const std::array<rgb::VertexId, 3> corners = mesh.face_vertices(hit->face);
    const auto engine_start = std::chrono::steady_clock::now();
    const rgb::SetLevelStats stats = apply_dab(mesh, footprint, active_mode(), brush_, hit->point, radius);
    timing_.last_ms = milliseconds_since(engine_start);
    timing_.last_footprint = footprint.size();
    ++timing_.dabs;
    stroke_changed_ |= stats.splits + stats.removals > 0;

    last_hit_ = hit;
    last_radius_ = radius;
    if (!mesh.is_live(hit->face)) reseed_after_dab(corners);
}

// The hit face may have been split or merged away; any live face at one of its corners serves as
// the next pick's seed.
void Editor::reseed_after_dab(const std::array<rgb::VertexId, 3>& corners) {
    const rgb::Mesh& mesh = document_.mesh();
    for (rgb::VertexId v : corners) {
        if (!mesh.is_live(v)) continue;
        last_hit_->face = rgb::Mesh::face(mesh.vertex_halfedge(v));
        return;
    }
    last_hit_.reset();
}

// ---- whole-mesh actions -----------------------------------------------------------------------

void Editor::frame_mesh() {
    const render::BoundingSphere bounds = document_.geometry().bounds(document_.mesh());
    camera_.refit(bounds, viewport_);
}

void Editor::reset_view() { camera_.frame(document_.geometry().bounds(document_.mesh()), viewport_); }

bool Editor::undo() {
    if (busy()) return false;
    const std::string label = document_.history().can_undo() ? document_.history().undo_label() : "";
    if (!document_.undo()) return false;
    report("undid " + label, false);
    return true;
}

bool Editor::redo() {
    if (busy()) return false;
    const std::string label = document_.history().can_redo() ? document_.history().redo_label() : "";
    if (!document_.redo()) return false;
    report("redid " + label, false);
    return true;
}

void Editor::start_flood_fill(int level) {
    if (busy()) return;
    job_ = std::make_unique<FloodFillJob>(document_.mesh(), std::clamp(level, 0, kMaxBrushLevel));
    document_.begin_edit(job_->label());
}

void Editor::start_auto_lod() {
    if (busy()) return;
    job_ = std::make_unique<AutoLodJob>(document_.mesh(), auto_lod_settings_);
    document_.begin_edit(job_->label());
}

// Work done until the cancel stays, as one undoable step.
void Editor::cancel_job() {
    if (!job_) return;
    report(job_->label() + " cancelled; Ctrl+Z undoes what it did", false);
    document_.end_edit(job_->changed());
    job_.reset();
}

void Editor::finish_job() {
    report(job_->label() + " done", false);
    document_.end_edit(job_->changed());
    job_.reset();
}

bool Editor::sample_level_under_cursor() {
    const std::optional<SurfaceHit> hit = cursor_hit();
    if (!hit) return false;
    brush_.target_level = document_.mesh().level(hit->face);
    return true;
}

// ---- files and confirmations ------------------------------------------------------------------

bool Editor::open(const std::string& path) {
    if (busy()) return false;
    try {
        const std::vector<std::string> warnings = document_.open(path);
        report(warnings.empty() ? "opened " + path : path + ": " + warnings.front() +
                                                         (warnings.size() > 1 ? " (and more)" : ""),
               false);
    } catch (const rgbio::ObjError& error) {
        report(error.what(), true);
        return false;
    }
    remember_recent(path);
    reset_view();
    return true;
}

bool Editor::save() {
    if (document_.path().empty()) {
        report("the mesh has no file yet: use Save as", true);
        return false;
    }
    return save_as(document_.path());
}

bool Editor::save_as(const std::string& path) {
    if (busy()) return false;
    try {
        const rgbio::SaveReport saved = document_.save(path, save_options_);
        std::string note = "saved " + path;
        if (saved.limit_fallbacks > 0)
            note += " (" + std::to_string(saved.limit_fallbacks) + " vertices at displayed positions: no limit yet)";
        report(note, false);
    } catch (const rgbio::SaveError& error) {
        report(error.what(), true);
        return false;
    }
    remember_recent(path);
    return true;
}

void Editor::request_open(const std::string& path) {
    if (document_.dirty()) {
        pending_ = Pending::DiscardForOpen;
        pending_path_ = path;
    } else {
        open(path);
    }
}

void Editor::request_save_as(const std::string& path) {
    std::error_code error;
    if (path != document_.path() && std::filesystem::exists(path, error)) {
        pending_ = Pending::Overwrite;
        pending_path_ = path;
    } else {
        save_as(path);
    }
}

void Editor::request_quit() {
    if (document_.dirty()) pending_ = Pending::DiscardForQuit;
    else quit_ = true;
}

void Editor::files_dropped(std::span<const std::string> paths) {
    if (!paths.empty()) request_open(paths.front());
}

void Editor::answer_pending(bool proceed) {
    const Pending question = std::exchange(pending_, Pending::None);
    if (!proceed) return;
    switch (question) {
        case Pending::DiscardForQuit: quit_ = true; break;
        case Pending::DiscardForOpen: open(pending_path_); break;
        case Pending::Overwrite: save_as(pending_path_); break;
        case Pending::None: break;
    }
}

void Editor::remember_recent(const std::string& path) {
    std::erase(recent_, path);
    recent_.insert(recent_.begin(), path);
    if (recent_.size() > kMaxRecentFiles) recent_.resize(kMaxRecentFiles);
}

void Editor::report(std::string message, bool error) {
    message_ = std::move(message);
    message_is_error_ = error;
}

std::string Editor::window_title() const { return document_title(document_) + " - rgbsub"; }

}  // namespace app
