// Export LODs in the editor (docs/editor.md "Export LODs"): the levels `rgbsub lods` writes, made of
// the mesh as it is in the background, previewed one at a time in the viewport, and written.
#include <stdexcept>
#include <utility>

#include "app/editor.h"
#include "io/base_attributes.h"
#include "io/formats/mesh_format.h"
#include "io/scale_check.h"
#include "io/script/triangle_limit.h"

namespace app {

void Editor::start_lod_levels() { start_lods(std::nullopt); }

void Editor::start_lod_export(const std::string& path) {
    lod_export_.output = path;
    if (path.empty()) {
        lod_problem_ = "no file to export to: type a path (a .glb or .gltf file holds every level; another format writes one file per level)";
        return;
    }
    start_lods(path);
}

void Editor::start_lods(const std::optional<std::string>& output) {
    lod_problem_.clear();
    if (lod_task_) {
        lod_problem_ = "the LODs are being made: wait, or press Esc to stop";
        return;
    }
    // The mesh of a stroke or job under way is not the one the user will see when it ends.
    if (refuse_if_busy(output ? "export LODs" : "make LODs")) {
        lod_problem_ = message_;
        return;
    }
    const rgb::Mesh& mesh = document_.mesh();
    rgbio::LodSetOptions options;
    // As `rgbsub lods` without options: limit positions (a cage's detail positions), the state in OBJ
    // levels, what rides on the base mesh; .msh levels in the encoding the Files panel asks for.
    rgbio::SaveOptions save;
    save.positions = rgbio::lod_set_positions(mesh);
    save.msh = save_options_.msh;
    options.save = document_.with_attributes(save);
    // Every level's error is measured at the tolerance criterion's samples (command_lods.cpp).
    options.max_triangles = rgbio::editor_triangle_limit(rgbio::MemoryUse::Tolerance);
    options.output = output;
    std::vector<rgbio::ScriptLine> requests;
    try {
        requests = rgbio::lod_set_requests(lod_export_.criterion, lod_export_.values, mesh);
        rgbio::check_lod_set_size(mesh, requests, options.max_triangles);
        if (output && rgbio::output_format(*output) == rgbio::OutputFormat::Gltf)
            if (const std::optional<std::string> problem = rgbio::scale_problem(mesh.base().positions(), rgbio::kFloatScale))
                throw std::invalid_argument("cannot write " + *output + " (glTF keeps 32-bit floats): " + *problem);
    } catch (const std::invalid_argument& refused) {
        lod_problem_ = std::string(rgbio::lod_set_option(lod_export_.criterion) + 2) + ": " + refused.what();
        return;
    } catch (const rgbio::TooLarge& refused) {
        lod_problem_ = refused.what();
        return;
    }
    lod_notes_ = output ? rgbio::dropped_skin(options.save.attributes.get(), *output) : std::vector<std::string>();
    lod_task_changes_ = document_.changes();
    lod_task_ = BackgroundTask::lods(mesh, std::move(requests), std::move(options));
}

void Editor::poll_lod_task() {
    // Levels of a mesh that has changed since are not its levels any more.
    if (lod_levels_ && lod_levels_->changes != document_.changes()) {
        lod_levels_.reset();
        lod_preview_.reset();
    }
    if (!lod_task_ || !lod_task_->done()) return;
    const std::unique_ptr<BackgroundTask> task = std::move(lod_task_);
    if (task->error()) {
        lod_problem_ = (task->path().empty() ? "could not make the LODs: " : "could not export the LODs to " + task->path() + ": ") + *task->error();
        report(lod_problem_, true);
        return;
    }
    if (lod_task_changes_ != document_.changes()) return;  // the mesh changed meanwhile: nothing to preview
    lod_levels_.emplace(task->take_lods());
    lod_levels_->changes = lod_task_changes_;
    ++lod_sets_made_;
    lod_preview_.reset();
    const std::size_t n = lod_levels_->set.levels.size();
    if (!task->path().empty()) {
        std::string files = rgbio::output_format(task->path()) == rgbio::OutputFormat::Gltf
                                ? task->path()
                                : rgbio::lod_file_name(task->path(), 0) + " to " + rgbio::lod_file_name(task->path(), n - 1);
        std::string message = "exported " + std::to_string(n) + " LODs to " + files;
        for (const std::vector<std::string>* notes : {&lod_notes_, &lod_levels_->set.warnings})
            for (const std::string& note : *notes) message += "; " + note;
        report(std::move(message), false);
    } else {
        report("made " + std::to_string(n) + " LODs: the slider in Export LODs shows each", false);
    }
}

void Editor::stop_lods() {
    if (!lod_task_) return;
    lod_task_.reset();
    report("stopped making the LODs", false);
}

const LodLevels* Editor::lod_levels() const {
    return lod_levels_ && lod_levels_->changes == document_.changes() ? &*lod_levels_ : nullptr;
}

void Editor::preview_lod(std::optional<std::size_t> level) {
    const LodLevels* levels = lod_levels();
    lod_preview_ = levels && level && *level < levels->set.levels.size() ? level : std::nullopt;
}

std::optional<std::size_t> Editor::previewed_lod() const { return lod_levels() ? lod_preview_ : std::nullopt; }

std::optional<Editor::LodPreview> Editor::lod_preview() const {
    const std::optional<std::size_t> level = previewed_lod();
    if (!level) return std::nullopt;
    return LodPreview{&lod_levels_->set.levels[*level].mesh, &lod_levels_->displays[*level], (lod_sets_made_ << 16) + *level + 1};
}

}  // namespace app
