// `rgbsub edit [FILE.obj]`: the editor window (src/app). Without a display it says so and points
// to the headless command instead of failing inside GLFW.
#include <cstdlib>
#include <iostream>

#include "app/editor_window.h"
#include "cli/arguments.h"
#include "cli/commands.h"

namespace cli {

int run_edit(std::span<const std::string> args) {
    const Arguments arguments(args, {}, {"--frames"});
    if (arguments.has("--help")) {
        std::cout << "usage: rgbsub edit [FILE.obj] [--frames N]\n"
                     "Opens the editor window (needs a display) on FILE.obj, or on the default mesh.\n"
                     "  --frames N   quit after N frames and print the time to the first frame\n";
        return exit_ok;
    }
    if (arguments.positional().size() > 1) throw UsageError("expects at most one FILE.obj");
    app::WindowLaunch launch;
    launch.file = arguments.positional().empty() ? app::default_mesh_path() : arguments.positional().front();
    if (arguments.has("--frames")) launch.frames = static_cast<int>(arguments.integer("--frames", 1, 1, 1000000));
    if (std::getenv("DISPLAY") == nullptr) {
        std::cerr << "rgbsub edit: no display (DISPLAY is not set); headless alternative: rgbsub render\n";
        return exit_bad_input;
    }
    return app::run_editor_window(launch);
}

}  // namespace cli
