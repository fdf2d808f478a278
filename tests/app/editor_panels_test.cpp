// The panels and dialogs (draw_panels) in an ImGui context of their own, fed input the way the
// window's backend feeds it, without a window or GL: Esc closes the file browser, and the panel's
// rows stay where they are whatever the document holds, so nothing moves under the cursor. And the
// window's input queue: no click or key tap is lost however slow the frames.
#include <filesystem>
#include <string>

#include <imgui.h>
#include <imgui_internal.h>  // the panel window's content size

#include <gtest/gtest.h>

#include "app/crease_tool.h"
#include "app/editor.h"
#include "app/editor_panels.h"
#include "app/ui_input_queue.h"
#include "test_paths.h"
#include "textured_quad.h"

namespace app {
namespace {

// Where the harness keeps Esc among ImGui's key slots (the GLFW backend uses GLFW's key codes).
constexpr int kEscapeSlot = 256;

// An ImGui context of the display size given, without a settings file, its font atlas built (NewFrame
// needs one), for a test that runs frames of its own.
ImGuiIO& create_imgui_context(ImVec2 display) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = display;
    io.DeltaTime = 1.0f / 60.0f;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    return io;
}

class Panels : public ::testing::Test {
protected:
    Panels() { create_imgui_context(ImVec2(1280.0f, 800.0f)).KeyMap[ImGuiKey_Escape] = kEscapeSlot; }
    ~Panels() override { ImGui::DestroyContext(); }

    void frame() {
        ImGui::NewFrame();
        draw_panels(editor, state, options);
        ImGui::Render();
    }
    // The height of everything in the side panel, once it has settled (ImGui measures a frame late).
    float panel_rows_height() {
        frame();
        frame();
        return ImGui::FindWindowByName("rgbsub")->ContentSize.y;
    }

    Editor editor{glm::ivec2(1280, 800)};
    PanelState state;
    render::RenderOptions options;
};

TEST_F(Panels, EscClosesTheFileBrowser) {
    editor.key_pressed(Key::O, {.ctrl = true});
    frame();
    ASSERT_EQ(state.browser.purpose, FileBrowser::Purpose::Open);
    ImGui::GetIO().KeysDown[kEscapeSlot] = true;
    frame();
    ImGui::GetIO().KeysDown[kEscapeSlot] = false;
    frame();
    EXPECT_EQ(state.browser.purpose, FileBrowser::Purpose::None);
    EXPECT_EQ(ImGui::GetTopMostPopupModal(), nullptr) << "the modal closed: the editor gets its keys again";
}

// Rows that appeared with the state (recent files, texture coordinates, crease tags, the crease
// tool's hint) pushed every row below them down under a resting cursor.
TEST_F(Panels, RowsStayWhereTheyAreWhateverTheDocumentHolds) {
    const float fresh = panel_rows_height();

    const std::filesystem::path quad = test::write_textured_quad(test::fresh_folder("panel_rows_quad"));
    ASSERT_TRUE(editor.open(quad.string())) << editor.message();
    ASSERT_TRUE(editor.document().uv_interpolation().has_value());
    EXPECT_EQ(panel_rows_height(), fresh) << "with texture coordinates and a recent file";

    ASSERT_TRUE(editor.open(test::asset_path("default.obj"))) << editor.message();
    ASSERT_TRUE(editor.set_sharp_features(with_edges_above(editor.document().mesh(), 30.0), "tag edges above 30 degrees"));
    editor.crease_tool().active = true;
    editor.start_flood_fill(1);
    editor.finish_work();
    EXPECT_EQ(panel_rows_height(), fresh) << "with crease tags, the crease tool on and an undo step";
}

// The window's queue (ui_input_queue.h): a click and a key tap whose press and release both came
// between two frames each reach ImGui, the click where it was pressed.
class QueuedInput : public ::testing::Test {
protected:
    QueuedInput() { create_imgui_context(ImVec2(400.0f, 300.0f)); }
    ~QueuedInput() override { ImGui::DestroyContext(); }

    // One frame with a button at (0, 0)-(100, 40) of the display.
    void frame() {
        queue.deliver(ImGui::GetIO());
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
        ImGui::Begin("##buttons", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize);
        ImGui::SetCursorScreenPos(ImVec2(0.0f, 0.0f));
        clicks += ImGui::Button("press me", ImVec2(100.0f, 40.0f));
        key_presses += ImGui::IsKeyPressed(kTappedSlot, false);
        ImGui::End();
        ImGui::Render();
    }

    static constexpr int kTappedSlot = 65;
    UiInputQueue queue{{{300, 301}, {302, 303}, {304, 305}, {306, 307}}};
    int clicks = 0, key_presses = 0;
};

TEST_F(QueuedInput, APressAndItsReleaseBetweenTwoFramesBothReachImGui) {
    queue.mouse_moved(ImVec2(300.0f, 200.0f));
    frame();
    frame();  // the window is shown (and hoverable) from its second frame
    // All of a quick click, from afar, before the next frame.
    queue.mouse_moved(ImVec2(50.0f, 20.0f));
    queue.mouse_button(ImGuiMouseButton_Left, true);
    queue.mouse_button(ImGuiMouseButton_Left, false);
    queue.mouse_moved(ImVec2(300.0f, 200.0f));
    for (int i = 0; i < 4; ++i) frame();
    EXPECT_EQ(clicks, 1);
    EXPECT_TRUE(queue.empty());

    queue.key(kTappedSlot, true);
    queue.key(kTappedSlot, false);
    for (int i = 0; i < 3; ++i) frame();
    EXPECT_EQ(key_presses, 1);
    EXPECT_FALSE(ImGui::GetIO().KeysDown[kTappedSlot]);
}

}  // namespace
}  // namespace app
