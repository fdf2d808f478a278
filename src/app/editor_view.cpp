#include "app/editor_view.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include <glm/vec4.hpp>

#include "app/editor.h"

namespace app {
namespace {

// The axis gizmo's size: its axes' length, and its centre's distance from the window's left edge and
// from the status bar.
constexpr float kGizmoLength = 34.0f, kGizmoMargin = 52.0f;
// How far above the status bar the gizmo reaches (its "ortho"/"persp" label, kGizmoMargin + 4 above its
// centre), plus a gap: the legend of a heat map starts above it instead of under it.
constexpr float kGizmoHeight = 2.0f * kGizmoMargin + 4.0f + 6.0f;

// The mesh frame's axes as the camera sees them, in the bottom left corner: X red, Y green, Z blue,
// the farthest drawn first so that the nearest lies on top.
void draw_axis_gizmo(const render::OrbitCamera& camera) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const ImVec2 centre(kGizmoMargin, display.y - kStatusBarHeight - kGizmoMargin);
    struct Axis {
        glm::vec4 direction;
        ImU32 colour;
        const char* name;
        float depth = 0.0f;
        ImVec2 tip{};
    };
    std::array<Axis, 3> axes{{{{1, 0, 0, 0}, IM_COL32(230, 60, 60, 255), "X"},
                              {{0, 1, 0, 0}, IM_COL32(80, 200, 80, 255), "Y"},
                              {{0, 0, 1, 0}, IM_COL32(70, 120, 240, 255), "Z"}}};
    const glm::mat4 view = camera.view();
    for (Axis& axis : axes) {
        const glm::vec4 seen = view * axis.direction;
        axis.depth = seen.z;
        axis.tip = ImVec2(centre.x + kGizmoLength * seen.x, centre.y - kGizmoLength * seen.y);
    }
    std::sort(axes.begin(), axes.end(), [](const Axis& a, const Axis& b) { return a.depth < b.depth; });
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    draw->AddCircleFilled(centre, kGizmoLength + 12.0f, IM_COL32(40, 40, 40, 90));
    for (const Axis& axis : axes) {
        draw->AddLine(centre, axis.tip, axis.colour, 3.0f);
        draw->AddCircleFilled(axis.tip, 8.0f, axis.colour);
        draw->AddText(ImVec2(axis.tip.x - 4.0f, axis.tip.y - 7.0f), IM_COL32(255, 255, 255, 255), axis.name);
    }
    draw->AddText(ImVec2(centre.x - kGizmoMargin + 6.0f, centre.y - kGizmoMargin - 4.0f), IM_COL32(90, 90, 90, 255),
                  camera.orthographic ? "ortho" : "persp");
}

// F / Ctrl+F: the circle whose radius is the value, the value beside the pointer. The lazy mouse:
// the string from the brush to the pointer while painting.
void draw_brush_feedback(const Editor& editor) {
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const ImVec2 pointer(editor.pointer().x, editor.pointer().y);
    if (const std::optional<BrushAdjust>& adjust = editor.brush_adjust()) {
        const ImVec2 centre(adjust->centre.x, adjust->centre.y);
        const float radius = std::hypot(pointer.x - centre.x, pointer.y - centre.y);
        const ImU32 colour = IM_COL32(255, 140, 0, 255);
        draw->AddCircle(centre, std::max(radius, 1.0f), colour, 96, 2.0f);
        draw->AddLine(centre, pointer, IM_COL32(255, 140, 0, 160), 1.0f);
        draw->AddCircleFilled(centre, 3.0f, colour);
        const std::string label = brush_adjust_label(*adjust, editor.brush());
        const ImVec2 at(pointer.x + 14.0f, pointer.y - 22.0f), size = ImGui::CalcTextSize(label.c_str());
        draw->AddRectFilled(ImVec2(at.x - 4.0f, at.y - 2.0f), ImVec2(at.x + size.x + 4.0f, at.y + size.y + 2.0f), IM_COL32(30, 30, 30, 200), 3.0f);
        draw->AddText(at, IM_COL32(255, 255, 255, 255), label.c_str());
    }
    if (const std::optional<glm::vec2> lazy = editor.lazy_point()) {
        const ImVec2 brush(lazy->x, lazy->y);
        draw->AddLine(brush, pointer, IM_COL32(90, 90, 90, 220), 1.5f);
        draw->AddCircleFilled(brush, 3.5f, IM_COL32(255, 140, 0, 255));
    }
}

}  // namespace

EditorView::EditorView() { apply_settings(EditorSettings()); }

void EditorView::apply_settings(const EditorSettings& settings) {
    const DisplaySettings& display = settings.display;
    options_.shading = display.shading;
    options_.colouring = display.colouring;
    options_.wireframe = display.wireframe;
    options_.base_mesh_overlay = display.base_mesh;
    options_.positions = display.limit_positions ? render::PositionSource::Limit : render::PositionSource::Displayed;
    panels_.layout = settings.panel;
}

void EditorView::take_settings(EditorSettings& settings) const {
    DisplaySettings& display = settings.display;
    display.shading = options_.shading;
    display.colouring = options_.colouring;
    display.wireframe = options_.wireframe;
    display.base_mesh = options_.base_mesh_overlay;
    display.limit_positions = options_.positions == render::PositionSource::Limit;
    settings.panel = panels_.layout;
}

void EditorView::draw(Editor& editor, glm::ivec2 framebuffer, bool show_cursor) {
    Document& document = editor.document();
    draw_panels(editor, panels_, options_);
    options_.bottom_inset_px = kStatusBarHeight + (axis_gizmo_ ? kGizmoHeight : 0.0f);
    // The document's displayed triangles as far as they have caught up (Editor::update), which
    // picking uses too: the renderer uploads what changed.
    document.set_position_source(options_.positions);
    document.set_detail_distance(options_.colouring == render::Colouring::DetailDistance);
    const Document::DisplayChanges changes = document.take_display_changes();
    // A level of Export LODs previewed in place of the mesh: uploaded whole when it comes and when
    // the mesh comes back.
    const std::optional<Editor::LodPreview> preview = editor.lod_preview();
    const std::uint64_t shown = preview ? preview->serial : 0;
    if (preview) renderer_.show(*preview->mesh, *preview->display, {}, shown != shown_);
    else renderer_.show(document.mesh(), document.shown(), changes.ranges, changes.rebuilt || shown != shown_);
    shown_ = shown;

    options_.brush.reset();
    // While F or Ctrl+F adjusts the brush, its own circle stands for the brush.
    if (show_cursor && !ImGui::GetIO().WantCaptureMouse && !editor.brush_adjust() && !preview)
        if (const auto hit = editor.cursor_hit()) {
            // Orange where a drag adds detail, blue where it removes it (coarsen, or Shift).
            const bool removes = editor.active_mode() == BrushMode::Coarsen ||
                                 (editor.active_mode() == BrushMode::Set && editor.active_level() < editor.document().mesh().level(hit->face));
            options_.brush = render::BrushCursor{glm::vec3(hit->point), static_cast<float>(editor.brush_world_radius(hit->point)),
                                                 removes ? glm::vec3(0.2f, 0.55f, 1.0f) : glm::vec3(1.0f, 0.55f, 0.0f)};
        }
    renderer_.draw(editor.camera().camera(), options_, framebuffer);
    if (axis_gizmo_) draw_axis_gizmo(editor.camera().camera());
    draw_brush_feedback(editor);
}

}  // namespace app
