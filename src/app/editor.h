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
#include <deque>
#include <exception>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "app/auto_lod.h"
#include "app/background_task.h"
#include "app/brush.h"
#include "app/brush_adjust.h"
#include "app/crease_tool.h"
#include "app/detail_job.h"
#include "app/display_pace.h"
#include "app/document.h"
#include "app/history_job.h"
#include "app/lod_levels.h"
#include "app/input.h"
#include "app/mesh_job.h"
#include "app/recovery_store.h"
#include "app/request_job.h"
#include "app/stroke_sampler.h"
#include "app/stroke_script.h"
#include "app/surface_picking.h"
#include "app/view_camera.h"
#include "app/view_lod_job.h"
#include "io/mesh_file.h"
#include "io/script/triangle_limit.h"

namespace app {

// A question the user must answer before the editor goes on.
// DenseMesh: a plain mesh above EditorOptions::dense_mesh_triangles was read; make a cage of it that
// keeps its detail, or open it as a base mesh (answer_dense_mesh). RemeshFailed: the cage could not
// be made (pending_message() says why); answering only closes the dialog.
enum class Pending { None, DiscardForQuit, DiscardForOpen, Overwrite, Recover, DenseMesh, RemeshFailed };

// A plain mesh with more triangles than this is offered a cage when it is opened (Pending::DenseMesh).
inline constexpr std::size_t kDenseMeshTriangles = 200000;
// The recent files kept, newest first.
inline constexpr std::size_t kMaxRecentFiles = 8;
// The cage offered: this share of the dense mesh's triangles, at least the topology's smallest.
inline constexpr double kCageShare = 0.005;

struct EditorOptions {
    glm::ivec2 viewport{1280, 800};
    // Where recovery copies of unsaved work go (recovery_store.h); none: no copies are kept.
    std::optional<std::filesystem::path> recovery_folder;
    int process_id = 0;  // names this session's copy; 0: this process
    float covered_right = 0.0f;  // see set_covered_right
    // Unsaved work is copied this often (and before whole-mesh actions).
    std::chrono::seconds recovery_interval{120};
    // Opening a plain mesh with more triangles asks first (Pending::DenseMesh).
    std::size_t dense_mesh_triangles = kDenseMeshTriangles;
    // The files that ship with rgbsub (the window: the source tree's assets): one opened from here is
    // a sample, which Save never writes over; its first save asks where (suggested_path()).
    std::optional<std::filesystem::path> samples_folder;
};

// What the engine and picking cost, for the statistics panel and the benchmarks.
struct EngineTiming {
    double frame_ms = 0.0;             // the jobs' work in the most recent update(), all its rounds
    std::size_t frame_operations = 0;  // splits and removals they made
    double geometry_ms = 0.0;          // bringing the picking geometry and index up to date in it
    CatchUpTiming catch_up;            // that catching up's parts
    double last_pick_ms = 0.0;         // picking the most recent dab and mapping it to base space
    double stroke_start_ms = 0.0;      // the press that started the most recent stroke
    std::size_t dabs = 0;
};

// The least time left in a frame for another round of work after the display caught up
// (Editor::update): a shorter one would cut the work into pieces too small to be worth it.
inline constexpr std::chrono::microseconds kMinWorkRound{2000};

// The side panel's width in pixels (editor_panels.cpp), and what it covers of the viewport with its
// margin: the window and headless frames tell the editor (set_covered_right) so that framing keeps
// the mesh clear of it.
inline constexpr float kPanelWidth = 320.0f;
inline constexpr float kPanelCover = kPanelWidth + 8.0f;

class Editor {
public:
    explicit Editor(glm::ivec2 viewport = {1280, 800});
    // With a recovery folder, offers (Pending::Recover) the newest copy a session that did not exit
    // cleanly left there.
    explicit Editor(const EditorOptions& options);

    Document& document() { return document_; }
    const Document& document() const { return document_; }
    ViewCamera& camera() { return camera_; }
    const ViewCamera& camera() const { return camera_; }
    BrushSettings& brush() { return brush_; }
    const BrushSettings& brush() const { return brush_; }
    AutoLodSettings& auto_lod_settings() { return auto_lod_settings_; }
    rgbio::SaveOptions& save_options() { return save_options_; }
    glm::ivec2 viewport() const { return viewport_; }
    void set_viewport(glm::ivec2 viewport);
    // Pixels at the right of the viewport that the panel covers: framing keeps the mesh out of them.
    void set_covered_right(float pixels) { covered_right_ = pixels; }

    // ---- input ----
    void mouse_moved(glm::vec2 px);
    void mouse_pressed(MouseButton button, Modifiers mods);
    void mouse_released(MouseButton button);
    void scrolled(float steps);
    void key_pressed(Key key, Modifiers mods);
    // Shift held or not, for the stroke under way and the cursor preview.
    void set_modifiers(Modifiers mods) { mods_ = mods; }
    // Advances the queued work (strokes, whole-mesh jobs) and brings the display up to date with it
    // (as far as it can), both within about a time slice (display_pace.h), takes the results of
    // files read or written in the background and keeps the recovery copy; call once per frame.
    void update(std::chrono::microseconds slice);
    // Runs the queued work and the files being read or written to their end (tests, headless frames).
    void finish_work();
    // Whether frames must keep coming without input: a stroke, a whole-mesh job or a file task under
    // way, or a display that has not caught up with the mesh (Document::display_up_to_date). The
    // window waits for input otherwise.
    bool needs_frames() const;

    // ---- brush ----
    bool painting() const { return painting_; }
    // Where the brush would touch the surface now, and its world radius there.
    std::optional<SurfaceHit> cursor_hit();
    double brush_world_radius(const glm::dvec3& at) const;
    BrushMode active_mode() const { return effective_mode(brush_.mode, mods_.shift); }
    // F (radius) or Ctrl+F (target) under way: the pointer's distance from its centre sets the value
    // (brush_adjust.h); a left click keeps it, a right click or Esc restores the old one.
    const std::optional<BrushAdjust>& brush_adjust() const { return adjust_; }
    // The lazy mouse's brush position while painting with BrushSettings::lazy_px (the pointer pulls
    // it on its string); none otherwise.
    std::optional<glm::vec2> lazy_point() const;
    glm::vec2 pointer() const { return mouse_; }
    int active_level() const { return effective_level(brush_, mods_.shift); }

    // ---- whole-mesh actions ----
    void frame_mesh();
    void reset_view();
    // A step of up to HistoryJob::kImmediateOperations crosses before these return; a larger one
    // continues in update() as the job under way (job()), which Esc stops part way (history_job.h).
    bool undo();
    bool redo();
    // Both refuse (with a message naming the estimate) a result above the triangle limit.
    void start_flood_fill(int level);
    void start_auto_lod();
    // The most triangles a whole-mesh action may make (default: sized to the machine's memory).
    std::size_t triangle_limit() const { return triangle_limit_; }
    void set_triangle_limit(std::size_t limit) { triangle_limit_ = limit; }
    // Esc: stops the work under way (what is done stays as one undoable step) and drops what waits.
    void cancel_job();
    // The work under way, if any: a stroke still being applied or a whole-mesh job.
    const MeshJob* job() const { return jobs_.empty() ? nullptr : jobs_.front().get(); }
    std::size_t jobs_waiting() const { return jobs_.empty() ? 0 : jobs_.size() - 1; }
    // The level of the face under the cursor becomes the brush's target level.
    bool sample_level_under_cursor();

    // ---- crease tool (crease_tool.h; editor_creases.cpp) ----
    CreaseToolSettings& crease_tool() { return crease_tool_; }
    // Gives the base mesh other crease tags as one undoable step; false (with a message) if refused.
    bool set_sharp_features(const rgb::SharpFeatures& features, std::string label);

    // ---- detail by size, accuracy and view (detail_job.h, view_lod_job.h; editor_detail.cpp) ----
    DetailSettings& detail_settings() { return detail_settings_; }
    // Max edge or tolerance over the whole mesh, a slice per frame: one undoable step.
    void start_detail_edit();
    // The view-dependent mode: every frame the detail follows the camera, until frozen.
    void start_view_lod();
    // Ends the view-dependent mode: the mesh stays as it is, one undoable step (Esc does the same;
    // saving and opening a file freeze it first).
    void freeze_view_lod();
    // The mode's job while it runs.
    ViewLodJob* view_lod() const;

    // ---- Export LODs (lod_levels.h; editor_lods.cpp) ----
    LodExportSettings& lod_export_settings() { return lod_export_; }
    // Makes the levels the settings ask for of the mesh as it is, as `rgbsub lods` makes them, in the
    // background (lod_task(); Esc stops it): lod_levels() has them once done. Bad values (an empty
    // list, a value out of range or twice) or a level too large are refused with lod_problem() set.
    void start_lod_levels();
    // The same, writing them to `path` as `rgbsub lods -o path` does (io/lod_set_files.h: a .glb or
    // .gltf path one file with MSFT_lod, another one file per level); a failed export writes nothing.
    void start_lod_export(const std::string& path);
    const BackgroundTask* lod_task() const { return lod_task_.get(); }
    // The levels made of the document as it is now; null if none (or the mesh has changed since).
    const LodLevels* lod_levels() const;
    // Why the last request for LODs was refused or failed ("" if it was not).
    const std::string& lod_problem() const { return lod_problem_; }
    // The viewport shows level `level` of lod_levels() in place of the mesh (none: the mesh again).
    // The document and its history stay as they are; an edit ends the preview.
    void preview_lod(std::optional<std::size_t> level);
    std::optional<std::size_t> previewed_lod() const;
    // The level previewed and its display (at its written positions), if any.
    struct LodPreview {
        const rgb::Mesh* mesh;
        const render::SurfaceGeometry* display;
        std::uint64_t serial;  // differs for every level of every set made (never 0)
    };
    std::optional<LodPreview> lod_preview() const;

    // ---- files ----
    // Right away, on this thread (tests, headless frames); each returns false and sets an error
    // message when it cannot proceed.
    bool open(const std::string& path);  // no questions asked
    // open, but a file that cannot be loaded throws its rgbio::ObjError (for callers that report it
    // themselves, like the CLI's screenshot) instead of setting the message.
    void load(const std::string& path);
    bool save();                         // to the document's path
    // A .glb or .gltf path exports: the document stays the file it was (Document::save).
    bool save_as(const std::string& path);
    // What the window does: read or write in the background (file_task() shows how it goes), and
    // ask first when there are unsaved changes (once the file has been read: a file that cannot be
    // read asks nothing) or the target exists. A save waits for the work under way.
    void request_open(const std::string& path);
    void request_save();
    void request_save_as(const std::string& path);
    void request_quit();
    // "Save and quit" in the quit question.
    void save_and_quit();
    const BackgroundTask* file_task() const { return file_task_.get(); }
    // Files dropped on the window: the first is opened as by request_open (the editor holds one mesh).
    void files_dropped(std::span<const std::string> paths);
    Pending pending() const { return pending_; }
    const std::string& pending_path() const { return pending_path_; }
    void answer_pending(bool proceed);
    // Pending::DenseMesh. The cage's triangle count the question offers (editable; the remesh gets it
    // as its budget), the least it may be (the topology's smallest cage), the dense mesh's count.
    std::size_t& cage_triangles() { return cage_triangles_; }
    std::size_t smallest_cage_triangles() const { return smallest_cage_; }
    std::size_t dense_triangles() const;
    // make_cage: remesh in the background (file_task(), kind Remesh; Esc stops it and leaves the
    // document as it was); on success the document is the cage with the detail at level 0, unsaved,
    // with suggested_path() (NAME_cage.obj) for Save. Otherwise the mesh opens as a base mesh.
    // answer_pending(false) opens nothing.
    void answer_dense_mesh(bool make_cage);
    // Where Save proposes to write a document that has no file of its own yet ("" if none): a cage
    // made here, or a sample (the same name in the home folder). Ctrl+S then opens the browser there
    // instead of refusing or writing over the sample.
    const std::string& suggested_path() const { return suggested_path_; }
    // The dialog's Stop while the cage is made (Esc does the same): the document stays as it was.
    void stop_remesh();
    // Pending::RemeshFailed's reason.
    const std::string& pending_message() const { return pending_message_; }
    // Once nothing is being saved.
    bool should_quit() const;
    // A clean exit: the recovery copy goes (after one being written is done).
    void close_session();
    // Absolute paths, newest first (at most kMaxRecentFiles).
    const std::vector<std::string>& recent_files() const { return recent_; }
    // Those of an earlier session (editor_settings.h).
    void set_recent_files(std::vector<std::string> paths);
    // A note in the status line from outside the editor (the window's settings file, say).
    void show_message(std::string message, bool error) { report(std::move(message), error); }
    // Ctrl+O, Ctrl+Shift+S and Ctrl+E ask the window for its file browser.
    enum class Browse { None, Open, SaveAs, SaveStrokes };
    Browse take_browse_request() { return std::exchange(browse_request_, Browse::None); }
    // Counts the files that could not be opened (the panel then shows the document's path again).
    std::uint64_t open_failures() const { return open_failures_; }
    const std::string& message() const { return message_; }
    bool message_is_error() const { return message_is_error_; }
    std::string window_title() const;

    // The edits in effect as a level-of-detail script (brush and dab lines, `level` for set all),
    // which `rgbsub apply` replays on the opened file to the same mesh. Returns false with a message
    // when it cannot be written; warns when some edit in effect has no script.
    bool save_strokes(const std::string& path);

    // ---- statistics ----
    const EngineTiming& timing() const { return timing_; }

    // ---- failures ----
    // Runs one input event or frame step. A std::exception from it (out of memory in a deep
    // request, say) is reported in the panel instead of ending the program, and the editor carries
    // on: a stroke or job under way is rolled back to the mesh before it, since the core may have
    // stopped half-way through an operation; earlier work and the undo history stay. Returns false
    // after a failure.
    bool run_guarded(const std::function<void()>& step);

private:
    void begin_brush_adjust(BrushAdjust::What what);
    void end_brush_adjust(bool keep);
    void begin_stroke(glm::vec2 px);
    void continue_stroke(glm::vec2 px);
    void end_stroke();
    void dab(glm::vec2 px);
    // A detail-size or tolerance dab (editor_detail.cpp): a max-edge or tolerance request in the
    // ball, applied whole.
    void detail_dab(const BaseSpaceHit& at, const glm::dvec3& hit_point);
    std::optional<SurfaceHit> pick(glm::vec2 px);
    void queue(std::unique_ptr<MeshJob> job);
    // Steps the queued jobs until `deadline`; true if they stopped with work left for more time
    // (not for lack of work: a converged view-dependent LOD, say).
    bool run_jobs(std::chrono::steady_clock::time_point deadline);
    // Undo or redo: at once, or as a job.
    bool cross(HistoryJob::Direction direction);
    // File tasks: start, and take what finished.
    void start_save(const std::string& path);
    void poll_file_task();
    // Esc while a file is read: the result is dropped (a save is never stopped half way).
    void stop_opening();
    void opened(LoadedDocument loaded, const std::string& path);
    // A file read, with the user's consent to replace the document: asks Pending::DenseMesh for a
    // dense plain mesh, opens it otherwise.
    void take_opened(LoadedDocument loaded, const std::string& path);
    // The document is now the file `path`, read with `warnings`: says so, resets the view.
    void show_opened(const std::string& path, const std::vector<std::string>& warnings);
    // Whether `path` lies in the samples folder (EditorOptions::samples_folder), and where Save then
    // proposes to write it ("" for any other file).
    bool is_sample(const std::string& path) const;
    std::string save_suggestion(const std::string& path) const;
    // Export LODs (editor_lods.cpp): start making (and writing) the levels; take the result.
    void start_lods(const std::optional<std::string>& output);
    void poll_lod_task();
    void stop_lods();
    // A remesh's result arrived (editor_files.cpp).
    void remeshed(BackgroundTask& task);
    // The recovery copy: written when `force`d or due, if there is unsaved work not yet in it.
    void keep_recovery_copy(bool force);
    void poll_recovery_task();
    // Nothing left unsaved (saved, opened, a clean exit): the copy goes, and the next change is
    // copied at once.
    void drop_recovery_copy();
    // Ends the job at the front (its edit with it) and starts on the next.
    void finish_front();
    void begin_crease_drag(bool untag);
    void crease_drag_to(glm::vec2 px);
    void end_crease_drag();
    void remember_recent(const std::string& path);
    // What the status line says after a glTF export.
    std::string exported_message(const std::string& path) const;
    void report(std::string message, bool error);
    void recover_from(const std::exception& failure);
    bool busy() const { return !jobs_.empty() || painting_ || crease_drag_.has_value(); }
    // Refuse (with a message) while work is under way / while a whole-mesh job is (strokes queue
    // behind strokes).
    bool refuse_if_busy(const char* action);
    bool refuse_if_whole_mesh_job(const char* action);

    Document document_;
    ViewCamera camera_;
    glm::ivec2 viewport_;
    BrushSettings brush_;
    AutoLodSettings auto_lod_settings_;
    std::size_t triangle_limit_ = rgbio::editor_triangle_limit(rgbio::MemoryUse::Level);
    rgbio::SaveOptions save_options_;

    glm::vec2 mouse_{0.0f};
    Modifiers mods_;
    enum class Drag { None, Orbit, Pan } drag_ = Drag::None;

    bool painting_ = false;
    std::optional<BrushAdjust> adjust_;
    glm::vec2 lazy_{0.0f};  // the lazy mouse's brush position in the stroke under way
    RequestJob* stroke_ = nullptr;  // the open stroke, in jobs_
    StrokeScript stroke_script_;
    StrokeSampler sampler_;
    std::optional<glm::dvec3> last_hit_point_;
    std::optional<SurfaceHit> cursor_hit_;
    EngineTiming timing_;

    // Applied in order, the front one a slice per frame; each is one undoable step, begun when it
    // reaches the front.
    std::deque<std::unique_ptr<MeshJob>> jobs_;
    bool front_begun_ = false;
    DisplayPace display_pace_;

    // Files read or written in the background, one at a time.
    std::unique_ptr<BackgroundTask> file_task_;
    std::optional<std::string> save_when_idle_;  // a save waiting for the work under way
    Document::SaveMark saved_mark_;                // the document's state in the copy being saved
    bool quit_after_save_ = false;
    std::optional<LoadedDocument> opened_;  // read, waiting for the answer to DiscardForOpen
    std::optional<LoadedDocument> dense_;   // read, waiting for the answer to DenseMesh
    std::size_t dense_mesh_triangles_ = kDenseMeshTriangles;
    std::size_t cage_triangles_ = 0;
    std::size_t smallest_cage_ = 0;
    std::string suggested_path_;
    std::optional<std::filesystem::path> samples_folder_;
    std::string pending_message_;
    bool remesh_drops_looks_ = false;  // the dense mesh had texture coordinates, colours or materials

    // Recovery copies of unsaved work.
    std::optional<RecoveryStore> recovery_;
    std::unique_ptr<BackgroundTask> recovery_task_;
    std::uint64_t recovery_changes_ = 0;  // the change count in the copy (being) written
    std::chrono::steady_clock::time_point recovery_due_;
    bool recovery_begun_ = false;  // a copy of the unsaved work has been written or tried
    std::chrono::seconds recovery_interval_{120};
    std::optional<RecoveryStore::Orphan> offered_;   // Pending::Recover's copy
    std::optional<RecoveryStore::Orphan> recovered_;  // removed once the own copy holds its work
    bool recovering_ = false;                          // file_task_ reads offered_

    float covered_right_ = 0.0f;
    // Memory held back for rolling an edit back after the edit ran out of memory (the rollback needs
    // a little itself): released before the rollback, taken again after it.
    std::unique_ptr<char[]> rollback_reserve_;
    Browse browse_request_ = Browse::None;
    std::uint64_t open_failures_ = 0;

    DetailSettings detail_settings_;

    LodExportSettings lod_export_;
    std::unique_ptr<BackgroundTask> lod_task_;
    std::uint64_t lod_task_changes_ = 0;  // Document::changes() of the mesh lod_task_ works on
    std::vector<std::string> lod_notes_;  // what the export leaves out (a skin)
    std::optional<LodLevels> lod_levels_;
    std::uint64_t lod_sets_made_ = 0;
    std::optional<std::size_t> lod_preview_;
    std::string lod_problem_;

    CreaseToolSettings crease_tool_;
    std::optional<CreaseDrag> crease_drag_;
    glm::vec2 crease_last_px_{0.0f};
    std::optional<SurfaceHit> crease_hit_;  // the last sample's hit

    Pending pending_ = Pending::None;
    std::string pending_path_;
    bool quit_ = false;
    std::vector<std::string> recent_;
    std::string message_;
    bool message_is_error_ = false;
};

}  // namespace app
