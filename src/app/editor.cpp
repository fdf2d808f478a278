#include "app/editor.h"

#include <algorithm>
#include <filesystem>
#include <new>
#include <thread>

#include <unistd.h>
#include <utility>

#include <glm/geometric.hpp>

#include "app/flood_fill.h"
#include "app/request_pieces.h"
#include "app/stroke_script.h"
#include "io/files/atomic_file.h"
#include "io/obj/obj_error.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/mesh.h"

namespace app {

namespace {
constexpr std::size_t kRollbackReserve = std::size_t{32} << 20;
}  // namespace
namespace {


EditorOptions options_for(glm::ivec2 viewport) {
    EditorOptions options;
    options.viewport = viewport;
    return options;
}

double milliseconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Editor::Editor(glm::ivec2 viewport) : Editor(options_for(viewport)) {}

Editor::Editor(const EditorOptions& options)
    : viewport_(options.viewport), recovery_interval_(options.recovery_interval), covered_right_(options.covered_right),
      rollback_reserve_(new char[kRollbackReserve]) {
    dense_mesh_triangles_ = options.dense_mesh_triangles;
    samples_folder_ = options.samples_folder;
    frame_mesh();
    recovery_due_ = std::chrono::steady_clock::now() + recovery_interval_;
    if (!options.recovery_folder) return;
    recovery_.emplace(*options.recovery_folder, options.process_id != 0 ? options.process_id : static_cast<int>(::getpid()));
    const std::vector<RecoveryStore::Orphan> orphans = recovery_->orphans();
    if (orphans.empty()) return;
    offered_ = orphans.front();
    pending_ = Pending::Recover;
    pending_path_ = offered_->document_path;
}

void Editor::set_viewport(glm::ivec2 viewport) { viewport_ = glm::max(viewport, glm::ivec2(1)); }

// ---- input ------------------------------------------------------------------------------------

void Editor::mouse_moved(glm::vec2 px) {
    const glm::vec2 delta = px - mouse_;
    mouse_ = px;
    if (adjust_) {
        adjust_brush(*adjust_, px, brush_);
        return;
    }
    if (drag_ == Drag::Orbit) camera_.orbit(delta);
    if (drag_ == Drag::Pan) camera_.pan(delta, viewport_);
    if (painting_) continue_stroke(px);
    if (crease_drag_) crease_drag_to(px);
}

void Editor::mouse_pressed(MouseButton button, Modifiers mods) {
    mods_ = mods;
    if (adjust_) {
        end_brush_adjust(button == MouseButton::Left);
        return;
    }
    if (drag_ != Drag::None || painting_) return;
    // Navigation never conflicts with painting: right/middle drag, or Alt with the left button.
    if (button == MouseButton::Right || (button == MouseButton::Left && mods.alt && !mods.shift)) {
        drag_ = Drag::Orbit;
    } else if (button == MouseButton::Middle || (button == MouseButton::Left && mods.alt && mods.shift)) {
        drag_ = Drag::Pan;
    } else if (button == MouseButton::Left && pending_ == Pending::None && crease_tool_.active) {
        if (!refuse_if_busy("tag creases")) begin_crease_drag(mods.shift);
    } else if (button == MouseButton::Left && pending_ == Pending::None && !refuse_if_whole_mesh_job("paint")) {
        begin_stroke(mouse_);
    }
}

void Editor::mouse_released(MouseButton button) {
    if (button == MouseButton::Left && painting_) end_stroke();
    if (button == MouseButton::Left && crease_drag_) end_crease_drag();
    if (button != MouseButton::Left || drag_ != Drag::None) drag_ = Drag::None;
}

// Towards the surface under the cursor, or the point of the cursor's ray as deep as the target.
void Editor::scrolled(float steps) {
    const Ray ray = camera_.ray_through(mouse_, viewport_);
    const std::optional<SurfaceHit> hit = pick(mouse_);
    const glm::dvec3 target(camera_.camera().target);
    const glm::dvec3 anchor = hit ? hit->point : ray.origin + ray.direction * glm::dot(target - ray.origin, ray.direction);
    camera_.zoom(steps, anchor);
}

void Editor::key_pressed(Key key, Modifiers mods) {
    mods_ = mods;
    // Blender's numpad: front, right and top, Ctrl for the opposite side; 5 toggles the projection.
    switch (key) {
        case Key::Keypad1: camera_.look_from(mods.ctrl ? ViewCamera::Axis::Back : ViewCamera::Axis::Front); return;
        case Key::Keypad3: camera_.look_from(mods.ctrl ? ViewCamera::Axis::Left : ViewCamera::Axis::Right); return;
        case Key::Keypad7: camera_.look_from(mods.ctrl ? ViewCamera::Axis::Bottom : ViewCamera::Axis::Top); return;
        case Key::Keypad5: camera_.set_orthographic(!camera_.camera().orthographic); return;
        default: break;
    }
    if (mods.ctrl) {
        switch (key) {
            case Key::Z: mods.shift ? redo() : undo(); break;
            case Key::Y: redo(); break;
            case Key::S:
                if (mods.shift) browse_request_ = Browse::SaveAs;
                else request_save();
                break;
            case Key::O: browse_request_ = Browse::Open; break;
            case Key::E: browse_request_ = Browse::SaveStrokes; break;
            case Key::Q: request_quit(); break;
            case Key::F: begin_brush_adjust(BrushAdjust::What::Target); break;
            default: break;
        }
        return;
    }
    switch (key) {
        case Key::F: begin_brush_adjust(BrushAdjust::What::Radius); break;
        case Key::Home: frame_mesh(); break;
        case Key::R: reset_view(); break;
        case Key::S: sample_level_under_cursor(); break;
        case Key::LeftBracket: grow_radius(brush_, -1); break;
        case Key::RightBracket: grow_radius(brush_, 1); break;
        case Key::Minus: brush_.target_level = std::max(brush_.target_level - 1, 0); break;
        case Key::Equal: brush_.target_level = std::min(brush_.target_level + 1, kMaxBrushLevel); break;
        case Key::Digit1: brush_.mode = BrushMode::Refine; break;
        case Key::Digit2: brush_.mode = BrushMode::Coarsen; break;
        case Key::Digit3: brush_.mode = BrushMode::Set; break;
        case Key::Escape:
            if (adjust_) end_brush_adjust(false);
            else if (pending_ != Pending::None) answer_pending(false);
            else if (view_lod()) freeze_view_lod();
            else if (!jobs_.empty()) cancel_job();
            else if (lod_task_) stop_lods();
            else stop_opening();
            break;
        default: break;
    }
}

void Editor::update(std::chrono::microseconds slice) {
    poll_file_task();
    poll_lod_task();
    poll_recovery_task();
    const auto start = std::chrono::steady_clock::now();
    const auto frame_end = start + slice;
    timing_.frame_ms = timing_.geometry_ms = 0.0;
    timing_.frame_operations = 0;
    timing_.catch_up = {};
    document_.take_catch_up_timing();  // what picking caught up before this frame
    // Rounds of work and catching up, both within the slice: the work stops early by what the
    // display is expected to need to show it (display_pace.h), and time the display did not need
    // goes back to the work in another round.
    for (;;) {
        const auto round = std::chrono::steady_clock::now();
        const auto left = std::chrono::duration_cast<std::chrono::microseconds>(frame_end - round);
        const std::size_t behind = document_.display_backlog();
        // View-dependent LOD bounds its own changes a step.
        const auto deadline = frame_end - display_pace_.display_share(left, behind, view_lod() ? view_lod()->max_face_changes() : 0);
        const bool stopped = run_jobs(deadline);
        const auto catch_up = std::chrono::steady_clock::now();
        timing_.frame_ms += std::chrono::duration<double, std::milli>(catch_up - round).count();
        const std::size_t made = document_.display_backlog();
        display_pace_.work_changed(made > behind ? made - behind : 0);
        // The picking geometry and index catch up here rather than in the next pick, within what
        // is left of the slice (but a part at least, so that they keep up with work that overran
        // its share). View-dependent LOD changes what is in view every frame: a display caught up
        // in part would show holes and overlaps where faces already replaced meet faces not yet,
        // so its frames catch up whole (its step stops at a quarter of a part's worth of changes,
        // Editor::start_view_lod).
        bool caught_up = true;
        if (view_lod()) document_.geometry();
        else caught_up = document_.catch_up_display(std::chrono::duration_cast<std::chrono::microseconds>(frame_end - catch_up), display_pace_);
        timing_.geometry_ms += milliseconds_since(catch_up);
        const CatchUpTiming caught = document_.take_catch_up_timing();
        display_pace_.caught_up(caught);
        timing_.catch_up.add(caught);
        if (!stopped || !caught_up || frame_end - std::chrono::steady_clock::now() < kMinWorkRound) break;
    }
    keep_recovery_copy(false);
}

bool Editor::run_jobs(std::chrono::steady_clock::time_point deadline) {
    // The front job gets the time; one that finishes early hands the rest to the next.
    while (!jobs_.empty()) {
        MeshJob& job = *jobs_.front();
        if (!front_begun_) {
            if (job.makes_edit()) document_.begin_edit(job.label());
            front_begun_ = true;
        }
        const auto left = std::chrono::duration_cast<std::chrono::microseconds>(deadline - std::chrono::steady_clock::now());
        const auto* requests = dynamic_cast<const RequestJob*>(&job);
        const std::size_t before = requests ? requests->stats().splits + requests->stats().removals : 0;
        const bool more = job.step(std::max(left, std::chrono::microseconds(0)));
        if (requests) timing_.frame_operations += requests->stats().splits + requests->stats().removals - before;
        // View-dependent LOD stops at its cap of changes before the deadline, and has more to do
        // until it converges.
        if (more) return std::chrono::steady_clock::now() >= deadline || (view_lod() && !view_lod()->converged());
        finish_front();
        if (std::chrono::steady_clock::now() >= deadline) return !jobs_.empty();
    }
    return false;
}

void Editor::finish_work() {
    if (stroke_) end_stroke();
    // The view-dependent mode never ends by itself: it is done for now once settled for the camera.
    const auto working = [this] { return !jobs_.empty() && !(view_lod() && view_lod()->converged()); };
    while (working() || file_task_ || recovery_task_ || save_when_idle_ || lod_task_) {
        update(std::chrono::seconds(1));
        if (!working()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
}

bool Editor::needs_frames() const {
    return job() != nullptr || painting_ || file_task_ != nullptr || lod_task_ != nullptr || !document_.display_up_to_date();
}

void Editor::queue(std::unique_ptr<MeshJob> job) { jobs_.push_back(std::move(job)); }

void Editor::finish_front() {
    MeshJob& job = *jobs_.front();
    if (!job.is_stroke()) report(job.done_message(), false);
    if (job.makes_edit()) document_.end_edit(job.changed(), job.script());
    jobs_.pop_front();
    front_begun_ = false;
}

bool Editor::refuse_if_whole_mesh_job(const char* action) {
    if (jobs_.empty() || jobs_.back()->is_stroke()) return false;
    report(std::string("cannot ") + action + " while " + jobs_.back()->label() + " runs: wait, or press Esc to stop it", true);
    return true;
}

bool Editor::refuse_if_busy(const char* action) {
    if (!busy()) return false;
    report(std::string("cannot ") + action + " while " + (painting_ ? "painting" : jobs_.front()->label() + " runs") +
               ": wait, or press Esc to stop it",
           true);
    return true;
}

// ---- brush and strokes ------------------------------------------------------------------------

void Editor::begin_brush_adjust(BrushAdjust::What what) {
    // Not again while one runs (a held key repeats).
    if (adjust_ || painting_ || drag_ != Drag::None || crease_drag_ || pending_ != Pending::None) return;
    adjust_ = app::begin_brush_adjust(brush_, what, mouse_);
}

void Editor::end_brush_adjust(bool keep) {
    if (!keep) brush_ = adjust_->before;
    adjust_.reset();
}

std::optional<glm::vec2> Editor::lazy_point() const {
    if (!painting_ || brush_.lazy_px <= 0.0f) return std::nullopt;
    return lazy_;
}

double Editor::brush_world_radius(const glm::dvec3& at) const {
    if (brush_.unit == RadiusUnit::World) return brush_.radius_world;
    return brush_.radius_px * camera_.world_per_pixel(camera_.depth_of(at), viewport_);
}

std::optional<SurfaceHit> Editor::cursor_hit() {
    // No brush circle while the display catches up with a large change: picking now would do all of
    // the catching up in this frame.
    cursor_hit_ = document_.display_behind() ? std::nullopt : pick(mouse_);
    return cursor_hit_;
}

std::optional<SurfaceHit> Editor::pick(glm::vec2 px) { return document_.pick(camera_.ray_through(px, viewport_)); }

void Editor::begin_stroke(glm::vec2 px) {
    const auto start = std::chrono::steady_clock::now();
    painting_ = true;
    last_hit_point_.reset();
    auto stroke = std::make_unique<RequestJob>(document_.mesh(), "brush stroke", true);
    stroke_script_ = StrokeScript();
    stroke_ = stroke.get();
    queue(std::move(stroke));
    lazy_ = px;
    for (glm::vec2 p : sampler_.begin(px)) dab(p);
    timing_.stroke_start_ms = milliseconds_since(start);
}

void Editor::continue_stroke(glm::vec2 px) {
    // The lazy mouse: the brush moves only as far as the pointer pulls it on its string.
    if (brush_.lazy_px > 0.0f) {
        const float pulled = glm::distance(px, lazy_) - brush_.lazy_px;
        if (pulled <= 0.0f) return;
        lazy_ += glm::normalize(px - lazy_) * pulled;
        px = lazy_;
    }
    const float spacing = 1.0f / std::clamp(brush_.dabs_per_radius, kLeastDabsPerRadius, kMostDabsPerRadius);
    float spacing_px = spacing * brush_.radius_px;
    if (brush_.unit == RadiusUnit::World && last_hit_point_)
        spacing_px = static_cast<float>(spacing * brush_.radius_world /
                                        camera_.world_per_pixel(camera_.depth_of(*last_hit_point_), viewport_));
    for (glm::vec2 p : sampler_.move_to(px, spacing_px)) dab(p);
}

void Editor::end_stroke() {
    painting_ = false;
    if (stroke_) stroke_->close();
    stroke_ = nullptr;
    last_hit_point_.reset();
}

// Picks and queues: the engine applies the dab's pieces in update(), coarse to fine.
void Editor::dab(glm::vec2 px) {
    const auto pick_start = std::chrono::steady_clock::now();
    const std::optional<SurfaceHit> hit = pick(px);
    if (!hit) {
        last_hit_point_.reset();
        return;
    }
    const rgb::Mesh& mesh = document_.mesh();
    const double radius = brush_world_radius(hit->point);
    const auto displayed = document_.geometry().corners(hit->face);
    const BaseSpaceHit at = to_base_space(mesh, hit->face, displayed, hit->point, radius);
    timing_.last_pick_ms = milliseconds_since(pick_start);
    if (brush_.target != BrushSettings::Target::Level) {
        detail_dab(at, hit->point);
    } else {
        const rgb::Dab request = make_dab(brush_, mods_.shift, at, camera_.ray_through(px, viewport_).direction);
        const int from_level = mesh.level(hit->face);
        // The dab and its mirror images, in the order its script line applies them.
        std::string lines = stroke_script_.lines(request, brush_.mirror);
        for (const rgb::Dab& image : rgbio::with_mirror_images(request, brush_.mirror))
            stroke_->add([&mesh, image, from_level] { return dab_pieces(mesh, image, from_level); }, std::exchange(lines, std::string()));
    }
    ++timing_.dabs;
    last_hit_point_ = hit->point;
}

// ---- whole-mesh actions -----------------------------------------------------------------------

// Both fit the mesh into the part of the viewport the panel leaves free, centred there.
void Editor::frame_mesh() {
    const glm::ivec2 free_area(std::max(viewport_.x - static_cast<int>(covered_right_), 1), viewport_.y);
    camera_.refit(document_.geometry().bounds(document_.mesh()), free_area);
    camera_.pan({-0.5f * covered_right_, 0.0f}, viewport_);
}

void Editor::reset_view() {
    const glm::ivec2 free_area(std::max(viewport_.x - static_cast<int>(covered_right_), 1), viewport_.y);
    camera_.frame(document_.geometry().bounds(document_.mesh()), free_area);
    camera_.pan({-0.5f * covered_right_, 0.0f}, viewport_);
}

bool Editor::undo() { return cross(HistoryJob::Direction::Undo); }

bool Editor::redo() { return cross(HistoryJob::Direction::Redo); }

// A step of a few thousand operations crosses at once; a larger one goes on over the frames as a job.
bool Editor::cross(HistoryJob::Direction direction) {
    const bool undo = direction == HistoryJob::Direction::Undo;
    if (refuse_if_busy(undo ? "undo" : "redo")) return false;
    const UndoHistory& history = document_.history();
    std::string label = undo ? (history.can_undo() ? history.undo_label() : "") : (history.can_redo() ? history.redo_label() : "");
    if (!(undo ? document_.begin_undo() : document_.begin_redo())) return false;
    auto job = std::make_unique<HistoryJob>(document_, direction, std::move(label));
    if (document_.continue_crossing(HistoryJob::kImmediateOperations)) {
        report(job->done_message(), false);
        return true;
    }
    queue(std::move(job));
    front_begun_ = true;  // the crossing has begun; nothing was queued before it (refuse_if_busy)
    return true;
}

void Editor::start_flood_fill(int level) {
    if (refuse_if_busy("set all")) return;
    level = std::clamp(level, 0, kMaxBrushLevel);
    rgb::LevelRequest everywhere;
    everywhere.level = level;  // a Set over the whole surface
    try {
        rgbio::check_request_size(document_.mesh(), everywhere, triangle_limit_);
    } catch (const rgbio::TooLarge& refused) {
        report("set all to level " + std::to_string(level) + " refused: " + refused.what(), true);
        return;
    }
    keep_recovery_copy(true);
    document_.keep_room(static_cast<std::size_t>(rgb::estimated_triangles(document_.mesh(), everywhere)));
    queue(make_flood_fill(document_.mesh(), level));
}

void Editor::start_auto_lod() {
    if (refuse_if_busy("start automatic LOD")) return;
    try {
        rgbio::check_budget_size(auto_lod_settings_.triangle_budget, triangle_limit_);
    } catch (const rgbio::TooLarge& refused) {
        report(std::string("automatic LOD refused: ") + refused.what(), true);
        return;
    }
    keep_recovery_copy(true);
    document_.keep_room(auto_lod_settings_.triangle_budget);
    queue(std::make_unique<AutoLodJob>(document_.mesh(), auto_lod_settings_));
}

// Work done until the cancel stays, as one undoable step; work waiting is dropped.
void Editor::cancel_job() {
    if (jobs_.empty()) return;
    if (stroke_) end_stroke();
    MeshJob& front = *jobs_.front();
    if (front_begun_) {
        front.cancel();
        // Work stopped part way has no script (a script says whole requests): its label says why.
        const std::optional<std::string> script = front.script();
        if (front.makes_edit())
            document_.end_edit(front.changed(), script, script ? std::nullopt : std::optional(front.label() + ", stopped"));
    }
    report(front.cancelled_message(front_begun_ && front.changed()), false);
    jobs_.clear();
    front_begun_ = false;
}

bool Editor::sample_level_under_cursor() {
    const std::optional<SurfaceHit> hit = cursor_hit();
    if (!hit) return false;
    brush_.target_level = document_.mesh().level(hit->face);
    return true;
}

// Absolute, so that the list stays right in a session started from another folder.
void Editor::remember_recent(const std::string& path) {
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(path, error).lexically_normal();
    const std::string kept = error ? path : absolute.string();
    std::erase(recent_, kept);
    recent_.insert(recent_.begin(), kept);
    if (recent_.size() > kMaxRecentFiles) recent_.resize(kMaxRecentFiles);
}

void Editor::set_recent_files(std::vector<std::string> paths) {
    recent_ = std::move(paths);
    if (recent_.size() > kMaxRecentFiles) recent_.resize(kMaxRecentFiles);
}

void Editor::report(std::string message, bool error) {
    message_ = std::move(message);
    message_is_error_ = error;
}

// ---- failures ----------------------------------------------------------------------------------

bool Editor::run_guarded(const std::function<void()>& step) {
    try {
        step();
        return true;
    } catch (const std::exception& failure) {
        recover_from(failure);
        return false;
    }
}

void Editor::recover_from(const std::exception& failure) {
    const std::string action = jobs_.empty() ? "" : jobs_.front()->is_stroke() ? "the brush stroke" : jobs_.front()->label();
    const std::string cause = dynamic_cast<const std::bad_alloc*>(&failure) != nullptr ? std::string("out of memory")
                                                                                      : std::string(failure.what());
    painting_ = false;
    stroke_ = nullptr;
    last_hit_point_.reset();
    drag_ = Drag::None;
    jobs_.clear();
    front_begun_ = false;
    std::string outcome;
    rollback_reserve_.reset();
    try {
        if (document_.abandon_edit()) outcome = "; " + action + " was rolled back, the mesh is as before it";
    } catch (const std::exception&) {
        outcome = "; " + action + " could not be rolled back either: save under a new name and check the file";
    }
    rollback_reserve_.reset(new (std::nothrow) char[kRollbackReserve]);
    report((action.empty() ? cause : cause + " during " + action) + outcome, true);
}

std::string Editor::window_title() const { return document_title(document_) + " - rgbsub"; }

}  // namespace app
