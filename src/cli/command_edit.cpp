// Placeholder for the editor until src/app provides it: it proves the window path (GLFW + glad)
// and the no-display behaviour that run.sh relies on.
#include <glad/gl.h>
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <iostream>

#include "cli/arguments.h"
#include "cli/commands.h"

namespace cli {

int run_edit(std::span<const std::string> args) {
    const Arguments arguments(args, {}, {});
    if (arguments.has("--help")) {
        std::cout << "usage: rgbsub edit [FILE.obj]\nOpens the editor window (needs a display).\n";
        return exit_ok;
    }
    if (arguments.positional().size() > 1) throw UsageError("expects at most one FILE.obj");
    if (std::getenv("DISPLAY") == nullptr) {
        std::cerr << "rgbsub edit: no display (DISPLAY is not set); headless alternative: rgbsub render\n";
        return exit_bad_input;
    }
    if (!glfwInit()) {
        std::cerr << "rgbsub edit: cannot open a window on display " << std::getenv("DISPLAY")
                  << "; headless alternative: rgbsub render\n";
        return exit_bad_input;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWwindow* window = glfwCreateWindow(1280, 800, "rgbsub", nullptr, nullptr);
    if (window != nullptr) glfwMakeContextCurrent(window);
    if (window == nullptr || gladLoadGL(glfwGetProcAddress) == 0) {
        std::cerr << "rgbsub edit: cannot create an OpenGL 3.3 core context\n";
        glfwTerminate();
        return exit_bad_input;
    }
    while (!glfwWindowShouldClose(window)) {
        glClearColor(0.18f, 0.18f, 0.2f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        glfwSwapBuffers(window);
        glfwWaitEvents();
    }
    glfwDestroyWindow(window);
    glfwTerminate();
    return exit_ok;
}

}  // namespace cli
