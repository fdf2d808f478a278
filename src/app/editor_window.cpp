#include "app/editor_window.h"

#include <glad/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "app/editor.h"
#include "app/editor_view.h"

namespace app {
namespace {

using Clock = std::chrono::steady_clock;

Editor& editor_of(GLFWwindow* window) { return *static_cast<Editor*>(glfwGetWindowUserPointer(window)); }

Modifiers modifiers_of(int mods) {
    return {(mods & GLFW_MOD_SHIFT) != 0, (mods & GLFW_MOD_CONTROL) != 0, (mods & GLFW_MOD_ALT) != 0};
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
        case GLFW_KEY_LEFT_BRACKET: return Key::LeftBracket;
        case GLFW_KEY_RIGHT_BRACKET: return Key::RightBracket;
        case GLFW_KEY_1: return Key::Digit1;
        case GLFW_KEY_2: return Key::Digit2;
        case GLFW_KEY_3: return Key::Digit3;
        case GLFW_KEY_4: return Key::Digit4;
        case GLFW_KEY_5: return Key::Digit5;
        case GLFW_KEY_ESCAPE: return Key::Escape;
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

// Installed before ImGui's backend, which chains to them; ImGui gets first say over the panels.
void install_callbacks(GLFWwindow* window) {
    glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) {
        editor_of(w).mouse_moved(to_pixels(w, x, y));
    });
    glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int mods) {
        const std::optional<MouseButton> b = button_of(button);
        if (!b) return;
        if (action == GLFW_PRESS && !ImGui::GetIO().WantCaptureMouse) editor_of(w).mouse_pressed(*b, modifiers_of(mods));
        if (action == GLFW_RELEASE) editor_of(w).mouse_released(*b);
    });
    glfwSetScrollCallback(window, [](GLFWwindow* w, double, double dy) {
        if (!ImGui::GetIO().WantCaptureMouse) editor_of(w).scrolled(static_cast<float>(dy));
    });
    glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int mods) {
        editor_of(w).set_modifiers(modifiers_of(mods));
        if (action == GLFW_RELEASE || ImGui::GetIO().WantCaptureKeyboard) return;
        if (const std::optional<Key> k = key_of(key)) editor_of(w).key_pressed(*k, modifiers_of(mods));
    });
    glfwSetDropCallback(window, [](GLFWwindow* w, int count, const char** paths) {
        const std::vector<std::string> dropped(paths, paths + count);
        editor_of(w).files_dropped(dropped);
    });
    glfwSetWindowCloseCallback(window, [](GLFWwindow* w) {
        glfwSetWindowShouldClose(w, GLFW_FALSE);  // the editor decides, after asking
        editor_of(w).request_quit();
    });
}

GLFWwindow* open_window() {
    if (!glfwInit()) return nullptr;
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SAMPLES, 4);
    GLFWwindow* window = glfwCreateWindow(1280, 800, "rgbsub", nullptr, nullptr);
    if (window == nullptr) return nullptr;
    glfwMakeContextCurrent(window);
    if (gladLoadGL(glfwGetProcAddress) == 0) {
        glfwDestroyWindow(window);
        return nullptr;
    }
    glfwSwapInterval(1);
    return window;
}

void run_loop(GLFWwindow* window, Editor& editor, const WindowLaunch& launch, Clock::time_point start) {
    EditorView view;
    std::string title;
    auto last = Clock::now();
    for (int frame = 0; !glfwWindowShouldClose(window) && !editor.should_quit(); ++frame) {
        if (launch.frames && frame >= *launch.frames) break;
        // Idle: sleep until input arrives (but keep drawing while a job or a stroke runs).
        if (editor.job() != nullptr || editor.painting() || frame < 2) glfwPollEvents();
        else glfwWaitEventsTimeout(0.25);
        int fw = 1, fh = 1;
        glfwGetFramebufferSize(window, &fw, &fh);
        editor.set_viewport({fw, fh});
        editor.update();
        if (editor.window_title() != title) {
            title = editor.window_title();
            glfwSetWindowTitle(window, title.c_str());
        }
        const auto now = Clock::now();
        const double dt = std::chrono::duration<double>(now - last).count();
        last = now;
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        view.draw(editor, {fw, fh}, dt, glfwGetWindowAttrib(window, GLFW_HOVERED) != 0);
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        glfwSwapBuffers(window);
        if (frame == 0 && launch.frames)
            std::printf("first frame after %.1f ms\n",
                        std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    }
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
    GLFWwindow* window = open_window();
    if (window == nullptr) {
        std::cerr << "rgbsub edit: cannot open an OpenGL 3.3 core window; headless alternative: rgbsub render\n";
        glfwTerminate();
        return 2;
    }
    Editor editor;
    if (launch.file) editor.open(*launch.file);  // a load error shows in the panel
    glfwSetWindowUserPointer(window, &editor);
    install_callbacks(window);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini next to the user's files
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
    run_loop(window, editor, launch, start);
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
    return 0;
}

}  // namespace app
