#include "app/editor_view.h"

#include <imgui.h>

#include "app/editor.h"

namespace app {

void EditorView::draw(Editor& editor, glm::ivec2 framebuffer, double dt_s, bool show_cursor) {
    Document& document = editor.document();
    draw_panels(editor, panels_, options_, dt_s);
    // The document's displayed triangles, which picking uses too: the renderer uploads what changed.
    document.set_position_source(options_.positions);
    const render::SurfaceGeometry& geometry = document.geometry();
    const Document::DisplayChanges changes = document.take_display_changes();
    renderer_.show(document.mesh(), geometry, changes.ranges, changes.rebuilt);

    options_.brush.reset();
    if (show_cursor && !ImGui::GetIO().WantCaptureMouse)
        if (const auto hit = editor.cursor_hit())
            options_.brush = render::BrushCursor{glm::vec3(hit->point), static_cast<float>(editor.brush_world_radius(hit->point))};
    renderer_.draw(editor.camera().camera(), options_, framebuffer);
}

}  // namespace app
