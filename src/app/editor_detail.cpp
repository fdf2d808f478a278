// Detail by size, accuracy and view in the editor (docs/requests.md "Detail by size, accuracy and view"): the
// whole-mesh max-edge and tolerance edits, and the view-dependent mode with its freeze.
#include <stdexcept>

#include "app/editor.h"
#include "io/script/lod_script.h"
#include "io/script/triangle_limit.h"
#include "render/camera.h"

namespace app {

void Editor::start_detail_edit() {
    if (refuse_if_busy("change the detail")) return;
    rgbio::DetailEdit edit;
    edit.criterion = detail_settings_.criterion;
    edit.amount = detail_settings_.amount;
    std::unique_ptr<DetailJob> job;
    const std::size_t limit = rgbio::editor_triangle_limit(rgbio::memory_use(edit.criterion));
    try {
        // A request that cannot fit (a tolerance of 1e-300) is refused before the job starts.
        rgbio::check_detail_size(document_.mesh(), rgbio::detail_request(document_.mesh(), edit, limit), limit);
        job = std::make_unique<DetailJob>(document_.mesh(), edit, limit);
    } catch (const std::invalid_argument& refused) {
        report(refused.what(), true);
        return;
    } catch (const rgbio::TooLarge& refused) {
        report(refused.what(), true);
        return;
    }
    keep_recovery_copy(true);
    queue(std::move(job));
}

void Editor::start_view_lod() {
    if (refuse_if_busy("start view-dependent LOD")) return;
    keep_recovery_copy(true);
    rgb::ViewLodSettings settings;
    settings.pixels = detail_settings_.view_pixels;
    settings.max_triangles = rgbio::editor_triangle_limit(rgbio::MemoryUse::ScreenLod);
    // The camera of the frame being drawn: the job asks for it every step. A step does no more than
    // a quarter of what the display takes in one part (a few milliseconds), so that each frame can
    // show the whole mesh as the step left it within the frame's time.
    queue(std::make_unique<ViewLodJob>(document_.mesh(), settings, [this] { return render::screen_view(camera_.camera(), viewport_); },
                                       kDisplayPartFaces / 4));
}

void Editor::freeze_view_lod() {
    if (!view_lod()) return;
    jobs_.front()->cancel();
    if (front_begun_) {
        finish_front();
    } else {
        jobs_.pop_front();
    }
    report("view-dependent LOD frozen: the mesh is an ordinary state now (Ctrl+Z undoes the mode's changes)", false);
}

// The amount in the mesh's units: in pixels it is measured where the dab lands, so zooming in asks for
// finer detail (Blender's relative detail; a tolerance in pixels bounds the error seen on screen);
// the script line holds the world amount, so it replays.
void Editor::detail_dab(const BaseSpaceHit& at, const glm::dvec3& hit_point) {
    rgbio::DetailEdit edit;
    edit.criterion = brush_.target == BrushSettings::Target::Tolerance ? rgbio::DetailCriterion::Tolerance : rgbio::DetailCriterion::MaxEdge;
    const double size = brush_.detail_unit == RadiusUnit::ScreenPixels
                            ? brush_.detail_px * camera_.world_per_pixel(camera_.depth_of(hit_point), viewport_)
                            : static_cast<double>(brush_.detail_world);
    edit.amount = {size, false};
    switch (effective_mode(brush_.mode, mods_.shift)) {
        case BrushMode::Refine: edit.kind = rgb::RequestKind::Refine; break;
        case BrushMode::Coarsen: edit.kind = rgb::RequestKind::Coarsen; break;
        case BrushMode::Set: edit.kind = rgb::RequestKind::Set; break;
    }
    rgb::Mesh& mesh = document_.mesh();
    // Symmetric: a line for the dab and for each of its mirror images (their balls as a dab's).
    rgb::Dab ball;
    ball.centre = at.centre;
    for (const rgb::Dab& image : rgbio::with_mirror_images(ball, brush_.mirror)) {
        edit.sphere = rgb::Sphere{image.centre, at.radius};
        stroke_->add_whole(
            [&mesh, edit] {
                const rgbio::DetailOutcome outcome = rgbio::apply_detail_edit(mesh, edit, rgbio::editor_triangle_limit(rgbio::memory_use(edit.criterion)));
                return rgb::RequestStats{outcome.report.splits, outcome.report.removals, outcome.report.level_cap_bound};
            },
            rgbio::format_detail_line(edit) + "\n");
    }
}

ViewLodJob* Editor::view_lod() const { return jobs_.empty() ? nullptr : dynamic_cast<ViewLodJob*>(jobs_.front().get()); }

}  // namespace app
