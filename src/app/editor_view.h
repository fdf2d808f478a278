#pragma once
// One editor frame on the current GL context: the mesh through render::Renderer with the brush
// cursor, then the ImGui panels. Shared by the window and the headless `--ui` screenshot, so both
// show the same thing. The caller owns the ImGui context and its platform/renderer backends.
#include <cstdint>

#include <glm/vec2.hpp>

#include "app/editor_panels.h"
#include "app/editor_settings.h"
#include "render/renderer.h"

namespace app {

class Editor;

class EditorView {
public:
    // The display starts as DisplaySettings' defaults (the topology shown).
    EditorView();

    // Builds the ImGui frame (between ImGui::NewFrame and ImGui::Render) and draws the mesh.
    // Call ImGui_ImplOpenGL3_RenderDrawData afterwards.
    void draw(Editor& editor, glm::ivec2 framebuffer, bool show_cursor);

    render::RenderOptions& options() { return options_; }
    // The axis gizmo in the bottom left corner (on unless turned off).
    void show_axis_gizmo(bool on) { axis_gizmo_ = on; }
    // The window's own work in the last frame (the wait for input left out), for the statistics.
    void set_frame_ms(double ms) { panels_.frame_ms = ms; }
    // The display and the panel's layout kept between sessions (editor_settings.h).
    void apply_settings(const EditorSettings& settings);
    void take_settings(EditorSettings& settings) const;

private:
    render::Renderer renderer_;
    render::RenderOptions options_;
    PanelState panels_;
    bool axis_gizmo_ = true;
    std::uint64_t shown_ = 0;  // what the renderer showed last frame: the mesh (0) or a preview's serial
};

}  // namespace app
