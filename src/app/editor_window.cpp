#include "app/editor_window.h"

#include <glad/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>  // ErrorCheckEndFrameRecover, the windows' rectangles
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

#include <glm/common.hpp>

#include "app/editor.h"
#include "app/editor_settings.h"
#include "app/editor_view.h"
#include "app/ui_input_queue.h"
#include "app/job_pacer.h"

namespace app {
namespace {

using Clock = std::chrono::steady_clock;

// ImGui's key slots are GLFW's key codes (imgui_impl_glfw's io.KeyMap).
constexpr UiInputQueue::ModifierSlots kGlfwModifiers{{GLFW_KEY_LEFT_CONTROL, GLFW_KEY_RIGHT_CONTROL},
                                                        {GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT},
                                                        {GLFW_KEY_LEFT_ALT, GLFW_KEY_RIGHT_ALT},
                                                        {GLFW_KEY_LEFT_SUPER, GLFW_KEY_RIGHT_SUPER}};
// Frames drawn after the last event: ImGui shows what an input opened (a combo's list, a popup) a
// frame after it took the input.
constexpr int kFramesAfterInput = 2;

// Changed settings are written once they have been changed for this long (the idle loop wakes up
// every second to look) and at exit, so that a crash loses little and dragging a slider does not
// write the file every frame.
constexpr std::chrono::seconds kSettingsDelay{2};

// The settings file (editor_settings.h): read at start, written when what it holds has changed.
class SettingsKeeper {
public:
    SettingsKeeper() {
        const std::optional<std::filesystem::path> folder = settings_folder();
        if (!folder) return;
        file_ = settings_file(*folder);
        LoadedSettings loaded = load_settings(*file_);
        warning_ = std::move(loaded.warning);
        written_ = loaded.settings;
    }
    const EditorSettings& loaded() const { return written_; }
    // A damaged file, said on stderr and in the status line.
    void report(Editor& editor) const {
        if (!warning_) return;
        std::cerr << "rgbsub edit: " << *warning_ << "\n";
        editor.show_message(*warning_, true);
    }
    // `now`: at exit, without waiting for the delay.
    void keep(GLFWwindow* window, Editor& editor, const EditorView& view, bool now) {
        if (!file_ || failed_) return;
        EditorSettings current;
        take_settings(editor, current);
        view.take_settings(current);
        glfwGetWindowSize(window, &current.window_size.x, &current.window_size.y);
        current.window_size = glm::clamp(current.window_size, kLeastWindowSide, kMostWindowSide);
        if (current == written_) {
            changed_.reset();
            return;
        }
        if (!changed_) changed_ = Clock::now();
        if (!now && Clock::now() - *changed_ < kSettingsDelay) return;
        try {
            store_settings(*file_, current);
            written_ = current;
            changed_.reset();
        } catch (const std::exception& failure) {
            failed_ = true;  // said once; the session goes on with its settings unsaved
            editor.show_message(std::string("settings not saved: ") + failure.what(), true);
        }
    }

private:
    std::optional<std::filesystem::path> file_;
    std::optional<std::string> warning_;
    EditorSettings written_;
    std::optional<Clock::time_point> changed_;
    bool failed_ = false;
};

struct WindowState {
    Editor* editor = nullptr;
    UiInputQueue imgui_input{kGlfwModifiers};
    bool redraw = true;  // something happened since the last frame
    int settle_frames = 0;
};

WindowState& state_of(GLFWwindow* window) { return *static_cast<WindowState*>(glfwGetWindowUserPointer(window)); }
Editor& editor_of(GLFWwindow* window) { return *state_of(window).editor; }

Modifiers modifiers_of(int mods) {
    return {(mods & GLFW_MOD_SHIFT) != 0, (mods & GLFW_MOD_CONTROL) != 0, (mods & GLFW_MOD_ALT) != 0};
}

// The keys held now: a key event reports the modifiers as they were before it, so releasing Shift
// would leave "Shift held" on until the next event.
Modifiers held_modifiers(GLFWwindow* window) {
    auto held = [&](int a, int b) { return glfwGetKey(window, a) == GLFW_PRESS || glfwGetKey(window, b) == GLFW_PRESS; };
    return {held(GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT), held(GLFW_KEY_LEFT_CONTROL, GLFW_KEY_RIGHT_CONTROL),
            held(GLFW_KEY_LEFT_ALT, GLFW_KEY_RIGHT_ALT)};
}

std::optional<Key> key_of(int glfw_key) {
    switch (glfw_key) {
        case GLFW_KEY_F: return Key::F;
        case GLFW_KEY_R: return Key::R;
        case GLFW_KEY_Z: return Key::Z;
        case GLFW_KEY_Y: return Key::Y;
        case GLFW_KEY_S: return Key::S;
        case GLFW_KEY_O: return Key::O;
        case GLFW_KEY_Q: return Key::Q;
        case GLFW_KEY_E: return Key::E;
        case GLFW_KEY_LEFT_BRACKET: return Key::LeftBracket;
        case GLFW_KEY_RIGHT_BRACKET: return Key::RightBracket;
        case GLFW_KEY_MINUS: return Key::Minus;
        case GLFW_KEY_EQUAL: return Key::Equal;
        case GLFW_KEY_1: return Key::Digit1;
        case GLFW_KEY_2: return Key::Digit2;
        case GLFW_KEY_3: return Key::Digit3;
        case GLFW_KEY_4: return Key::Digit4;
        case GLFW_KEY_5: return Key::Digit5;
        case GLFW_KEY_ESCAPE: return Key::Escape;
        case GLFW_KEY_KP_1: return Key::Keypad1;
        case GLFW_KEY_KP_3: return Key::Keypad3;
        case GLFW_KEY_KP_5: return Key::Keypad5;
        case GLFW_KEY_KP_7: return Key::Keypad7;
        case GLFW_KEY_HOME: return Key::Home;
        default: return std::nullopt;
    }
}

std::optional<MouseButton> button_of(int glfw_button) {
    switch (glfw_button) {
        case GLFW_MOUSE_BUTTON_LEFT: return MouseButton::Left;
        case GLFW_MOUSE_BUTTON_RIGHT: return MouseButton::Right;
        case GLFW_MOUSE_BUTTON_MIDDLE: return MouseButton::Middle;
        default: return std::nullopt;
    }
}

// Window coordinates to framebuffer pixels (they differ on high-DPI screens).
glm::vec2 to_pixels(GLFWwindow* window, double x, double y) {
    int w = 1, h = 1, fw = 1, fh = 1;
    glfwGetWindowSize(window, &w, &h);
    glfwGetFramebufferSize(window, &fw, &fh);
    return {static_cast<float>(x) * static_cast<float>(fw) / static_cast<float>(std::max(w, 1)),
            static_cast<float>(y) * static_cast<float>(fh) / static_cast<float>(std::max(h, 1))};
}

// Whether a click at window position (x, y) belongs to the panels: a modal dialog is open, or an
// ImGui window drawn last frame covers the point. Decided at the click's own position: ImGui's
// WantCaptureMouse is from the previous frame's mouse position, so a click right after a jump of
// the pointer onto the panel went through to the mesh.
bool panels_take(double x, double y) {
    if (ImGui::GetTopMostPopupModal() != nullptr) return true;
    const ImVec2 p(static_cast<float>(x), static_cast<float>(y));
    for (ImGuiWindow* window : ImGui::GetCurrentContext()->Windows)
        if (window->WasActive && !window->Hidden && window->Rect().Contains(p)) return true;
    return false;
}

// ImGui's backend installs none of its own: the mouse, keys and wheel go to ImGui through the
// window's queue (ui_input_queue.h), the rest straight to the backend. Every callback runs through
// Editor::run_guarded: an exception must not unwind through GLFW's C frames (that terminates the
// program and loses the document).
void install_callbacks(GLFWwindow* window) {
    glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) {
        state_of(w).redraw = true;
        state_of(w).imgui_input.mouse_moved(ImVec2(static_cast<float>(x), static_cast<float>(y)));
        editor_of(w).run_guarded([&] { editor_of(w).mouse_moved(to_pixels(w, x, y)); });
    });
    glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int mods) {
        state_of(w).redraw = true;
        state_of(w).imgui_input.mouse_button(button, action == GLFW_PRESS);
        const std::optional<MouseButton> b = button_of(button);
        if (!b) return;
        double x = 0.0, y = 0.0;
        glfwGetCursorPos(w, &x, &y);
        editor_of(w).run_guarded([&] {
            // A click anywhere ends a brush adjustment (F, Ctrl+F), over the panel too.
            if (action == GLFW_PRESS && (editor_of(w).brush_adjust() || !panels_take(x, y)))
                editor_of(w).mouse_pressed(*b, modifiers_of(mods));
            if (action == GLFW_RELEASE) editor_of(w).mouse_released(*b);
        });
    });
    glfwSetScrollCallback(window, [](GLFWwindow* w, double dx, double dy) {
        state_of(w).redraw = true;
        state_of(w).imgui_input.scrolled(ImVec2(static_cast<float>(dx), static_cast<float>(dy)));
        double x = 0.0, y = 0.0;
        glfwGetCursorPos(w, &x, &y);
        if (!panels_take(x, y)) editor_of(w).run_guarded([&] { editor_of(w).scrolled(static_cast<float>(dy)); });
    });
    glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int mods) {
        state_of(w).redraw = true;
        if (action != GLFW_REPEAT) state_of(w).imgui_input.key(key, action == GLFW_PRESS);
        if (action == GLFW_RELEASE || ImGui::GetIO().WantCaptureKeyboard) return;
        if (const std::optional<Key> k = key_of(key)) editor_of(w).run_guarded([&] { editor_of(w).key_pressed(*k, modifiers_of(mods)); });
    });
    glfwSetDropCallback(window, [](GLFWwindow* w, int count, const char** paths) {
        state_of(w).redraw = true;
        const std::vector<std::string> dropped(paths, paths + count);
        editor_of(w).run_guarded([&] { editor_of(w).files_dropped(dropped); });
    });
    glfwSetWindowCloseCallback(window, [](GLFWwindow* w) {
        state_of(w).redraw = true;
        glfwSetWindowShouldClose(w, GLFW_FALSE);  // the editor decides, after asking
        editor_of(w).request_quit();
    });
    glfwSetCharCallback(window, [](GLFWwindow* w, unsigned int c) {
        state_of(w).redraw = true;
        ImGui_ImplGlfw_CharCallback(w, c);
    });
    glfwSetCursorEnterCallback(window, [](GLFWwindow* w, int entered) {
        state_of(w).redraw = true;
        ImGui_ImplGlfw_CursorEnterCallback(w, entered);
        if (!entered) state_of(w).imgui_input.mouse_left();
    });
    glfwSetWindowSizeCallback(window, [](GLFWwindow* w, int, int) { state_of(w).redraw = true; });
    glfwSetWindowFocusCallback(window, [](GLFWwindow* w, int focused) {
        state_of(w).redraw = true;
        ImGui_ImplGlfw_WindowFocusCallback(w, focused);
    });
}

GLFWwindow* open_window(glm::ivec2 size) {
    if (!glfwInit()) return nullptr;
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SAMPLES, 4);
    GLFWwindow* window = glfwCreateWindow(size.x, size.y, "rgbsub", nullptr, nullptr);
    if (window == nullptr) return nullptr;
    glfwMakeContextCurrent(window);
    if (gladLoadGL(glfwGetProcAddress) == 0) {
        glfwDestroyWindow(window);
        return nullptr;
    }
    glfwSwapInterval(1);
    return window;
}

// Whether the frames only wait for a file read or written on another thread: then they come a few
// times a second, to move the progress bar and take the result, and leave the processor to it.
bool only_waiting_for_a_file(const Editor& editor) {
    return editor.job() == nullptr && !editor.painting() && editor.file_task() != nullptr && editor.document().display_up_to_date();
}

void run_loop(GLFWwindow* window, WindowState& state, const WindowLaunch& launch, Clock::time_point start, SettingsKeeper& settings) {
    Editor& editor = *state.editor;
    EditorView view;
    view.apply_settings(settings.loaded());
    JobPacer pacer;
    std::string title;
    bool file_shown = !launch.file;
    int frames_after_shown = 0;
    bool had_file_task = false;
    // Read in the background, so the window is there at once; after the recovery question, if
    // there is one, and not over recovered work.
    std::optional<std::string> to_open = launch.file;
    for (int frame = 0; !glfwWindowShouldClose(window) && !editor.should_quit(); ++frame) {
        if (to_open && editor.pending() == Pending::None && editor.file_task() == nullptr) {
            if (!editor.document().dirty()) editor.request_open(*to_open);
            to_open.reset();
        }
        if (launch.frames && file_shown && frames_after_shown >= *launch.frames) break;
        // Idle: sleep until input arrives (waking now and then for the recovery copy's timer), and
        // draw only if something happened. Counted frames (--frames) are always drawn, and so are
        // frames until the display has caught up with the mesh (Editor::needs_frames).
        if (only_waiting_for_a_file(editor) && frame >= 2) {
            glfwWaitEventsTimeout(0.05);
        } else if (editor.needs_frames() || frame < 2 || launch.frames || state.settle_frames > 0 || !state.imgui_input.empty()) {
            glfwPollEvents();
        } else {
            glfwWaitEventsTimeout(1.0);
            if (!state.redraw && !editor.needs_frames()) {
                const std::string message = editor.message();
                editor.run_guarded([&] { editor.update(pacer.slice()); });
                if (editor.message() == message && !editor.needs_frames()) {
                    settings.keep(window, editor, view, false);
                    continue;
                }
            }
        }
        if (std::exchange(state.redraw, false)) state.settle_frames = kFramesAfterInput;
        const auto frame_start = Clock::now();
        int fw = 1, fh = 1;
        glfwGetFramebufferSize(window, &fw, &fh);
        editor.set_viewport({fw, fh});
        editor.set_modifiers(held_modifiers(window));
        editor.run_guarded([&] { editor.update(pacer.slice()); });
        if (editor.window_title() != title) {
            title = editor.window_title();
            glfwSetWindowTitle(window, title.c_str());
        }
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        state.imgui_input.deliver(ImGui::GetIO());
        ImGui::NewFrame();
        const bool hovered = glfwGetWindowAttrib(window, GLFW_HOVERED) != 0;
        // A panel button may start work that fails; ImGui's window stack is then closed for it.
        if (!editor.run_guarded([&] { view.draw(editor, {fw, fh}, hovered); })) ImGui::ErrorCheckEndFrameRecover(nullptr);
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        glfwSwapBuffers(window);
        if (state.imgui_input.empty() && state.settle_frames > 0) --state.settle_frames;
        const double frame_ms = std::chrono::duration<double, std::milli>(Clock::now() - frame_start).count();
        view.set_frame_ms(frame_ms);
        pacer.frame_drawn(frame_ms - editor.timing().frame_ms);
        if (launch.frames && frame == 0)
            std::printf("first frame after %.1f ms\n", std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        if (!file_shown && editor.file_task() == nullptr && !to_open) {
            file_shown = true;
            if (launch.frames)
                std::printf("file shown after %.1f ms\n", std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        }
        frames_after_shown += file_shown;
        // A file task that ended in this frame (the cage made or stopped, a file read or saved) closed
        // its dialog, which ImGui takes off the screen only in the next frame: without one, the empty
        // "Making a cage" box stayed until the next input.
        const bool file_task = editor.file_task() != nullptr;
        if (std::exchange(had_file_task, file_task) && !file_task) state.settle_frames = kFramesAfterInput;
        settings.keep(window, editor, view, false);
    }
    settings.keep(window, editor, view, true);
}

}  // namespace

std::optional<std::string> default_mesh_path() {
    const std::string path = std::string(RGBSUB_ASSETS_DIR) + "/default.obj";
    std::error_code error;
    if (!std::filesystem::exists(path, error)) return std::nullopt;
    return path;
}

int run_editor_window(const WindowLaunch& launch) {
    const auto start = Clock::now();
    SettingsKeeper settings;
    GLFWwindow* window = open_window(settings.loaded().window_size);
    if (window == nullptr) {
        std::cerr << "rgbsub edit: cannot open an OpenGL 3.3 core window; headless alternative: rgbsub render\n";
        glfwTerminate();
        return 2;
    }
    EditorOptions options;
    options.recovery_folder = RecoveryStore::default_folder();
    options.covered_right = kPanelCover;
    options.samples_folder = RGBSUB_ASSETS_DIR;
    if (launch.cage_above) options.dense_mesh_triangles = *launch.cage_above;
    Editor editor(options);
    apply_settings(editor, settings.loaded());
    settings.report(editor);
    WindowState state;
    state.editor = &editor;
    glfwSetWindowUserPointer(window, &state);
    install_callbacks(window);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini next to the user's files
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window, false);
    ImGui_ImplOpenGL3_Init("#version 330 core");
    run_loop(window, state, launch, start, settings);
    if (editor.should_quit() || launch.frames) editor.close_session();
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
    // A file still being read when the user quit: its thread holds nothing worth waiting for, and
    // must not outlive the program's static objects.
    if (BackgroundTask::running() > 0) {
        std::fflush(nullptr);
        std::_Exit(0);
    }
    return 0;
}

}  // namespace app
