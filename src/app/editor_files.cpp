// The editor's files: opening and saving (right away, or in the background with the questions
// first), the questions themselves, the session's strokes as a script, and the recovery copy.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <thread>
#include <utility>

#include "app/editor.h"
#include "detail/cage.h"
#include "io/files/atomic_file.h"
#include "io/gltf_export.h"
#include "io/formats/mesh_format.h"
#include "io/mesh_export.h"
#include "io/obj/obj_error.h"

namespace app {

// ---- right away -------------------------------------------------------------------------------

bool Editor::open(const std::string& path) {
    if (refuse_if_busy("open a file")) return false;
    try {
        load(path);
    } catch (const rgbio::ObjError& error) {
        report(error.what(), true);
        ++open_failures_;
        return false;
    }
    return true;
}

void Editor::load(const std::string& path) { show_opened(path, document_.open(path)); }

void Editor::show_opened(const std::string& path, const std::vector<std::string>& warnings) {
    std::string message = warnings.empty() ? "opened " + path : path + ": " + warnings.front() + (warnings.size() > 1 ? " (and more)" : "");
    suggested_path_ = save_suggestion(path);
    if (!suggested_path_.empty())
        message += is_sample(path) ? " (a sample that ships with rgbsub: the first save asks where)"
                                   : " (read from another format: the first save asks where, proposing " + suggested_path_ + ")";
    report(message, false);
    remember_recent(path);
    reset_view();
    drop_recovery_copy();
}

bool Editor::is_sample(const std::string& path) const {
    if (!samples_folder_) return false;
    std::error_code error;
    std::filesystem::path folder = std::filesystem::weakly_canonical(*samples_folder_, error);
    if (error) return false;
    if (folder.filename().empty()) folder = folder.parent_path();  // written with a trailing separator
    const std::filesystem::path file = std::filesystem::weakly_canonical(path, error);
    if (error) return false;
    return std::mismatch(folder.begin(), folder.end(), file.begin(), file.end()).first == folder.end();
}

std::string Editor::save_suggestion(const std::string& path) const {
    // A mesh read from another format is saved as OBJ (which keeps the adaptive state) beside it,
    // never as OBJ text over the file it came from.
    if (!is_sample(path))
        return rgbio::mesh_format(path) == rgbio::MeshFormat::Obj ? ""
                                                                   : std::filesystem::path(path).replace_extension(".obj").string();
    // In the home folder: beside the sample would be among rgbsub's own files again.
    const char* home = std::getenv("HOME");
    std::error_code error;
    const std::filesystem::path folder =
        home != nullptr && std::filesystem::is_directory(home, error) ? std::filesystem::path(home) : std::filesystem::current_path(error);
    return (folder / std::filesystem::path(path).filename()).string();
}

bool Editor::save() {
    if (document_.path().empty() || !suggested_path_.empty()) {
        report("the mesh has no file of its own yet: use Save as", true);
        return false;
    }
    return save_as(document_.path());
}

bool Editor::save_as(const std::string& path) {
    if (refuse_if_busy("save")) return false;
    try {
        document_.save(path, save_options_);
    } catch (const rgbio::SaveError& error) {
        report(error.what(), true);
        return false;
    }
    if (rgbio::is_export_path(path)) {
        report(exported_message(path), false);
        return true;
    }
    report("saved " + path, false);
    suggested_path_.clear();
    remember_recent(path);
    drop_recovery_copy();
    return true;
}

std::string Editor::exported_message(const std::string& path) const {
    return "exported " + path + " (" + std::string(rgbio::format_name(rgbio::output_format(path))) +
           ", without the adaptive state: " + document_title(document_) + " stays the document)";
}

// The script replays on the file the history's edits start from, whatever the document was saved as
// since; a file saved over since holds some of the edits already, so replaying them there would
// apply them twice.
bool Editor::save_strokes(const std::string& path) {
    const UndoHistory::SessionScript session = document_.history().session_script();
    const std::string& start = document_.edits_start_from();
    const std::string opened = start.empty() ? std::string("the mesh") : start;
    const std::string saved_over =
        document_.start_file_saved_over() ? opened + " has been saved with these edits since: replay them on a copy of it as it was opened" : "";
    try {
        rgbio::write_file_atomically(path, "# rgbsub edit session on " + opened + ": rgbsub apply " + opened + " " + path +
                                               " -o OUT.obj replays it\n" + (saved_over.empty() ? "" : "# " + saved_over + "\n") +
                                               session.text);
    } catch (const rgbio::SaveError& error) {
        report(error.what(), true);
        return false;
    }
    std::string message = "saved the strokes to " + path + (saved_over.empty() ? "" : "; " + saved_over);
    if (session.unscripted_steps == 0) {
        report(message, false);
        return true;
    }
    std::string causes;
    for (const std::string& label : session.unscripted_labels) causes += (causes.empty() ? "" : ", ") + label;
    const bool one = session.unscripted_steps == 1;
    report(message + ", but " + std::to_string(session.unscripted_steps) + (one ? " edit in effect has" : " edits in effect have") +
               " no script (" + causes + "): a replay will differ",
           true);
    return true;
}

// ---- in the background, with questions ------------------------------------------------------

void Editor::request_open(const std::string& path) {
    freeze_view_lod();  // it would hold the opened file back for ever
    if (file_task_) {
        report("wait until " + file_task_->path() + " is " + (file_task_->kind() == BackgroundTask::Kind::Open ? "read" : "saved"), true);
        return;
    }
    file_task_ = BackgroundTask::open(path, document_.geometry().source());
    report("opening " + path + " ...", false);
}

void Editor::files_dropped(std::span<const std::string> paths) {
    if (!paths.empty()) request_open(paths.front());
}

void Editor::request_save() {
    if (!suggested_path_.empty()) {
        browse_request_ = Browse::SaveAs;  // a made document (a cage) or a sample: ask where, never over its source
        return;
    }
    if (document_.path().empty()) {
        report("the mesh has no file yet: use Save as", true);
        return;
    }
    start_save(document_.path());
}

void Editor::request_save_as(const std::string& path) {
    std::error_code error;
    if ((path != document_.path() || is_sample(path)) && std::filesystem::exists(path, error)) {
        pending_ = Pending::Overwrite;
        pending_path_ = path;
    } else {
        start_save(path);
    }
}

// The copy is made now, between frames, so the thread writing it shares nothing with the editor.
void Editor::start_save(const std::string& path) {
    freeze_view_lod();  // what is shown is saved, not a mesh that keeps changing
    if (file_task_) {
        report("wait until " + file_task_->path() + " is " + (file_task_->kind() == BackgroundTask::Kind::Open ? "read" : "saved"), true);
        return;
    }
    if (busy()) {
        save_when_idle_ = path;
        report("saving " + path + " once the work under way is done", false);
        return;
    }
    save_when_idle_.reset();
    saved_mark_ = document_.save_mark();
    file_task_ = BackgroundTask::save(document_.mesh(), path, document_.with_attributes(save_options_));
    report("saving " + path + " ...", false);
}

void Editor::poll_file_task() {
    if (save_when_idle_ && !busy() && !file_task_) start_save(*save_when_idle_);
    if (!file_task_ || !file_task_->done()) return;
    // A file read while strokes are still being applied waits for them: they belong to the mesh
    // on screen, and they are what makes it unsaved.
    if (file_task_->kind() == BackgroundTask::Kind::Open && busy()) return;
    const std::unique_ptr<BackgroundTask> task = std::move(file_task_);
    const bool recovering = std::exchange(recovering_, false);
    if (task->kind() == BackgroundTask::Kind::Remesh) {
        remeshed(*task);
        return;
    }
    if (task->error()) {
        report(*task->error(), true);
        quit_after_save_ = false;
        open_failures_ += task->kind() == BackgroundTask::Kind::Open;
        return;
    }
    if (task->kind() == BackgroundTask::Kind::Save && rgbio::is_export_path(task->path())) {
        report(exported_message(task->path()), false);
        return;
    }
    if (task->kind() == BackgroundTask::Kind::Save) {
        document_.saved_as(task->path(), saved_mark_);
        suggested_path_.clear();
        remember_recent(task->path());
        report("saved " + task->path() + " in " + std::to_string(static_cast<int>(task->seconds() * 1000.0)) + " ms", false);
        if (!document_.dirty()) drop_recovery_copy();
        quit_ = quit_ || quit_after_save_;
        return;
    }
    if (recovering) {
        document_.adopt(task->take_document(), offered_->document_path, true);
        suggested_path_ = save_suggestion(document_.path());
        recovered_ = std::exchange(offered_, std::nullopt);
        report("recovered the unsaved work" + (document_.path().empty() ? std::string() : " on " + document_.path()) +
                   ": save it to keep it",
               false);
        reset_view();
        keep_recovery_copy(true);
        return;
    }
    if (document_.dirty()) {
        // Read fine: now the question.
        opened_ = task->take_document();
        pending_ = Pending::DiscardForOpen;
        pending_path_ = task->path();
        return;
    }
    take_opened(task->take_document(), task->path());
}

void Editor::take_opened(LoadedDocument loaded, const std::string& path) {
    const rgb::Mesh& mesh = loaded.mesh;
    // A plain mesh: no detail, every face a base face (a saved adaptive file at level 0 counts too).
    const bool plain = mesh.base().detail() == nullptr && mesh.num_faces() == mesh.base().num_faces();
    if (!plain || mesh.base().num_faces() <= dense_mesh_triangles_) {
        opened(std::move(loaded), path);
        return;
    }
    try {
        smallest_cage_ = rgbdetail::smallest_cage_triangles(rgbdetail::topology_of(mesh.base().positions(), mesh.base().faces()));
    } catch (const std::exception& error) {
        // Not a mesh a cage can be made of: open it as before, and say why nothing was offered.
        opened(std::move(loaded), path);
        report(path + ": opened as a base mesh; no cage can be made of it: " + error.what(), false);
        return;
    }
    const auto share = static_cast<std::size_t>(kCageShare * static_cast<double>(mesh.base().num_faces()));
    cage_triangles_ = std::max(share, smallest_cage_);
    dense_ = std::move(loaded);
    pending_ = Pending::DenseMesh;
    pending_path_ = path;
    // The reading is over: the status line says what waits for the user, not "opening ...".
    report("read " + path + ": a cage of it, or the mesh as a base mesh?", false);
}

std::size_t Editor::dense_triangles() const { return dense_ ? dense_->mesh.base().num_faces() : 0; }

void Editor::answer_dense_mesh(bool make_cage) {
    if (pending_ != Pending::DenseMesh || !dense_) return;
    pending_ = Pending::None;
    LoadedDocument loaded = std::move(*dense_);
    dense_.reset();
    if (!make_cage) {
        opened(std::move(loaded), pending_path_);
        return;
    }
    if (cage_triangles_ < smallest_cage_) {
        pending_ = Pending::RemeshFailed;
        pending_message_ = "A cage of " + pending_path_ + " needs at least " + std::to_string(smallest_cage_) + " triangles.";
        report(pending_message_, true);
        return;
    }
    freeze_view_lod();
    const rgbio::BaseAttributes& looks = *loaded.attributes;
    remesh_drops_looks_ = loaded.uvs.has_value() || !looks.texcoords.empty() || !looks.colours.empty() || !looks.materials.empty();
    file_task_ = BackgroundTask::remesh(loaded.mesh.shared_base(), cage_triangles_, pending_path_, document_.geometry().source());
    report("making a cage of " + std::to_string(cage_triangles_) + " triangles for " + pending_path_ + " ...", false);
}

void Editor::remeshed(BackgroundTask& task) {
    if (task.error()) {
        pending_ = Pending::RemeshFailed;
        pending_path_ = task.path();
        pending_message_ = "Could not make a cage of " + task.path() + ":\n" + *task.error() + "\nNothing changed.";
        report("could not make a cage of " + task.path() + ": " + *task.error(), true);
        return;
    }
    cancel_job();  // nothing may go on working on the mesh being replaced
    document_.adopt(task.take_document(), std::string(), true);
    const std::filesystem::path source(task.path());
    suggested_path_ = (source.parent_path() / (source.stem().string() + "_cage.obj")).string();
    report("made " + task.summary() + ": unsaved, Save asks where (" + suggested_path_ + " proposed)" +
               (remesh_drops_looks_ ? "; its texture coordinates, colours and materials are not kept" : ""),
           false);
    reset_view();
    keep_recovery_copy(true);
}

void Editor::stop_remesh() {
    if (file_task_ && file_task_->kind() == BackgroundTask::Kind::Remesh) stop_opening();
}

void Editor::stop_opening() {
    if (file_task_ && file_task_->kind() == BackgroundTask::Kind::Remesh) {
        report("stopped making the cage of " + file_task_->path() + ": nothing changed", false);
        file_task_.reset();  // the remesh stops at its next progress report
        return;
    }
    if (!file_task_ || file_task_->kind() != BackgroundTask::Kind::Open) return;
    report("stopped opening " + file_task_->path(), false);
    file_task_.reset();
    recovering_ = false;
}

void Editor::opened(LoadedDocument loaded, const std::string& path) {
    cancel_job();  // nothing may go on working on the mesh being replaced
    const std::vector<std::string> warnings = std::move(loaded.warnings);
    document_.adopt(std::move(loaded), path);
    show_opened(path, warnings);
}

void Editor::request_quit() {
    if (file_task_ && file_task_->kind() == BackgroundTask::Kind::Save) {
        quit_after_save_ = true;
        report("quitting once " + file_task_->path() + " is saved", false);
    } else if (document_.dirty()) {
        pending_ = Pending::DiscardForQuit;
    } else {
        quit_ = true;
    }
}

void Editor::save_and_quit() {
    pending_ = Pending::None;
    if (document_.path().empty() || !suggested_path_.empty()) {
        report("the mesh has no file of its own yet: give it a name and use Save as", true);
        return;
    }
    request_save();
    quit_after_save_ = true;
}

bool Editor::should_quit() const { return quit_ && !(file_task_ && file_task_->kind() == BackgroundTask::Kind::Save) && !save_when_idle_; }

void Editor::answer_pending(bool proceed) {
    const Pending question = std::exchange(pending_, Pending::None);
    switch (question) {
        case Pending::DiscardForQuit: quit_ = proceed; break;
        case Pending::DiscardForOpen:
            if (proceed) take_opened(std::move(*opened_), pending_path_);
            opened_.reset();
            break;
        case Pending::Overwrite:
            if (proceed) start_save(pending_path_);
            break;
        case Pending::Recover:
            if (proceed) {
                recovering_ = true;
                file_task_ = BackgroundTask::open(offered_->mesh_file.string(), document_.geometry().source());
                report("recovering the unsaved work ...", false);
            } else {
                RecoveryStore::remove(*offered_);
                offered_.reset();
            }
            break;
        case Pending::DenseMesh:
            if (proceed) {
                pending_ = Pending::DenseMesh;
                answer_dense_mesh(true);
            } else {
                report("did not open " + pending_path_, false);
                dense_.reset();
            }
            break;
        case Pending::RemeshFailed: pending_message_.clear(); break;
        case Pending::None: break;
    }
}

// ---- the recovery copy ------------------------------------------------------------------------

// The first unsaved change is copied at once, so that no crash loses it; later ones on the timer.
void Editor::keep_recovery_copy(bool force) {
    if (!recovery_ || recovery_task_ || !document_.dirty() || document_.changes() == recovery_changes_) return;
    if (!force && recovery_begun_ && std::chrono::steady_clock::now() < recovery_due_) return;
    recovery_begun_ = true;
    try {
        recovery_->make_folder();
    } catch (const std::filesystem::filesystem_error& error) {
        report(std::string("cannot keep a recovery copy: ") + error.what(), true);
        recovery_due_ = std::chrono::steady_clock::now() + recovery_interval_;
        return;
    }
    recovery_changes_ = document_.changes();
    recovery_task_ = BackgroundTask::save(document_.mesh(), recovery_->mesh_file().string(), document_.with_attributes({}));
    recovery_due_ = std::chrono::steady_clock::now() + recovery_interval_;
}

void Editor::poll_recovery_task() {
    if (!recovery_task_ || !recovery_task_->done()) return;
    const std::unique_ptr<BackgroundTask> task = std::move(recovery_task_);
    if (task->error()) {
        report("cannot keep a recovery copy: " + *task->error(), true);
        recovery_changes_ = 0;
        return;
    }
    if (!document_.dirty()) {
        // Saved meanwhile: nothing to recover.
        drop_recovery_copy();
        return;
    }
    try {
        recovery_->write_note(document_.path());
    } catch (const rgbio::SaveError& error) {
        report(std::string("cannot keep a recovery copy: ") + error.what(), true);
        return;
    }
    if (recovered_) RecoveryStore::remove(*std::exchange(recovered_, std::nullopt));
}

void Editor::close_session() {
    while (recovery_task_ && !recovery_task_->done()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    recovery_task_.reset();
    drop_recovery_copy();
}

void Editor::drop_recovery_copy() {
    if (recovery_) recovery_->remove_own();
    recovery_begun_ = false;
}

}  // namespace app
