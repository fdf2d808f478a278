#pragma once
// The editor in a GLFW window: input from GLFW goes to app::Editor (unless an ImGui panel takes it),
// and each frame is drawn by app::EditorView.
#include <cstddef>
#include <optional>
#include <string>

namespace app {

struct WindowLaunch {
    std::optional<std::string> file;  // opened at start; the default mesh is the caller's choice
    // Quit after this many frames once the file is shown (benchmarks and smoke tests); prints the
    // times from launch to the first frame and to the file shown.
    std::optional<int> frames;
    // A plain mesh with more triangles is offered a cage that keeps its detail when opened
    // (`edit --cage-above N`); none: EditorOptions::dense_mesh_triangles's default.
    std::optional<std::size_t> cage_above;
};

// assets/default.obj of the source tree, if it is there (what `rgbsub` opens without a file).
std::optional<std::string> default_mesh_path();

// Returns a process exit code: 0, or 2 when no window can be opened (message on stderr).
int run_editor_window(const WindowLaunch& launch);

}  // namespace app
