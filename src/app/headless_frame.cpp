#include "app/headless_frame.h"

#include <glad/gl.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <stdexcept>

#include "app/editor.h"
#include "app/editor_view.h"
#include "render/offscreen_context.h"

namespace app {
namespace {

// ImGui needs a frame to measure auto-sized panels before they look as in the window.
constexpr int kSettleFrames = 3;

// ImGui's context for the lifetime of one headless frame.
struct ImGuiSession {
    ImGuiSession() {
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;
        ImGui::StyleColorsDark();
        if (!ImGui_ImplOpenGL3_Init("#version 330 core")) throw std::runtime_error("ImGui's OpenGL backend failed to start");
    }
    ~ImGuiSession() {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui::DestroyContext();
    }
    ImGuiSession(const ImGuiSession&) = delete;
    ImGuiSession& operator=(const ImGuiSession&) = delete;
};

}  // namespace

render::Image render_editor_frame(const std::string& file, const HeadlessFrame& frame) {
    Editor editor(frame.size);
    editor.set_covered_right(kPanelCover);
    editor.load(file);
    return render_editor_frame(editor, frame);
}

render::Image render_editor_frame(Editor& editor, const HeadlessFrame& frame) {
    editor.set_covered_right(kPanelCover);
    render::OffscreenContext context(frame.size.x, frame.size.y);
    ImGuiSession session;
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(frame.size.x), static_cast<float>(frame.size.y));
    io.DeltaTime = 1.0f / 60.0f;
    const glm::vec2 cursor = frame.cursor * glm::vec2(frame.size);
    io.MousePos = ImVec2(cursor.x, cursor.y);
    editor.mouse_moved(cursor);

    EditorView view;
    EditorSettings settings;
    view.take_settings(settings);
    settings.panel = frame.layout;
    view.apply_settings(settings);
    view.options().shading = frame.shading;
    view.options().colouring = frame.colouring;
    view.options().wireframe = frame.wireframe;
    view.show_axis_gizmo(frame.axis_gizmo);
    for (int i = 0; i < kSettleFrames; ++i) {
        ImGui_ImplOpenGL3_NewFrame();
        ImGui::NewFrame();
        view.draw(editor, frame.size, true);
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    }
    return context.read_pixels();
}

}  // namespace app
