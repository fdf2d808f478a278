#include "app/editor_view.h"

#include <imgui.h>

#include "app/editor.h"

namespace app {

void EditorView::draw(Editor& editor, glm::ivec2 framebuffer, double dt_s, bool show_cursor) {
    Document& document = editor.document();
    if (attached_generation_ != document.generation()) {
        // The mesh object was replaced (open, undo, redo): follow the new one.
        renderer_.detach();
        renderer_.attach(document.mesh());
        attached_generation_ = document.generation();
    }
    draw_panels(editor, panels_, options_, dt_s);
    renderer_.set_positions(options_.positions);

    options_.brush.reset();
    if (show_cursor && !ImGui::GetIO().WantCaptureMouse)
        if (const auto hit = editor.cursor_hit())
            options_.brush = render::BrushCursor{glm::vec3(hit->point), static_cast<float>(editor.brush_world_radius(hit->point))};
    renderer_.draw(editor.camera().camera(), options_, framebuffer);
}

}  // namespace app
