#include "app/editor_view.h"

#include <imgui.h>

#include "app/editor.h"

namespace app {

void EditorView::draw(Editor& editor, glm::ivec2 framebuffer, bool show_cursor) {
    Document& document = editor.document();
    draw_panels(editor, panels_, options_);
    options_.bottom_inset_px = kStatusBarHeight;
    // The document's displayed triangles as far as they have caught up (Editor::update), which
    // picking uses too: the renderer uploads what changed.
    document.set_position_source(options_.positions);
    document.set_detail_distance(options_.colouring == render::Colouring::DetailDistance);
    const render::SurfaceGeometry& geometry = document.shown();
    const Document::DisplayChanges changes = document.take_display_changes();
    renderer_.show(document.mesh(), geometry, changes.ranges, changes.rebuilt);

    options_.brush.reset();
    if (show_cursor && !ImGui::GetIO().WantCaptureMouse)
        if (const auto hit = editor.cursor_hit()) {
            // Orange where a drag adds detail, blue where it removes it (coarsen, or Shift).
            const bool removes = editor.active_mode() == BrushMode::Coarsen ||
                                 (editor.active_mode() == BrushMode::Set && editor.active_level() < editor.document().mesh().level(hit->face));
            options_.brush = render::BrushCursor{glm::vec3(hit->point), static_cast<float>(editor.brush_world_radius(hit->point)),
                                                 removes ? glm::vec3(0.2f, 0.55f, 1.0f) : glm::vec3(1.0f, 0.55f, 0.0f)};
        }
    renderer_.draw(editor.camera().camera(), options_, framebuffer);
}

}  // namespace app
