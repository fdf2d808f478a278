// `rgbsub edit [FILE.obj]`: the editor window (src/app). Without a display it says so and points
// to the headless command instead of failing inside GLFW.
#include <cstdlib>
#include <iostream>
#include <limits>
#include <stdexcept>

#include "app/editor.h"
#include "app/editor_window.h"
#include "app/headless_frame.h"
#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/mesh_io_support.h"
#include "io/files/atomic_file.h"
#include "io/mesh_reader.h"

namespace cli {
namespace {

// `--screenshot OUT.png`: one editor frame through OSMesa, no display needed.
int write_screenshot(const std::string& file, const std::string& output, const std::string& mode) {
    app::HeadlessFrame frame;
    if (mode == "rgb") {
        frame.shading = render::Shading::Flat;
        frame.colouring = render::Colouring::RgbType;
    } else if (mode == "level") {
        frame.colouring = render::Colouring::Level;
    } else if (mode == "wire") {
        frame.wireframe = true;
    } else if (mode == "material") {
        frame.colouring = render::Colouring::Material;
    } else if (mode == "colours") {
        frame.colouring = render::Colouring::VertexColour;
    } else if (mode == "checker") {
        frame.colouring = render::Colouring::Checker;
    } else if (mode == "texture") {
        frame.colouring = render::Colouring::Texture;
    } else if (mode == "distance") {
        frame.colouring = render::Colouring::DetailDistance;
    } else if (mode == "matcap") {
        frame.colouring = render::Colouring::Matcap;
    } else if (mode != "shaded") {
        throw UsageError("--mode must be shaded, wire, rgb, level, matcap, material, colours, checker, texture or distance, got '" + mode +
                         "'");
    }
    app::EditorOptions options;
    options.viewport = frame.size;
    options.covered_right = app::kPanelCover;
    app::Editor editor(options);
    editor.load(file);
    if (frame.colouring == render::Colouring::DetailDistance && !editor.document().mesh().base().detail())
        throw std::invalid_argument(file + ": --mode distance needs a cage with detail (made by rgbsub remesh), and this mesh has none");
    rgbio::write_file_atomically(output, render::encode_png(app::render_editor_frame(editor, frame)));
    return exit_ok;
}

}  // namespace

int run_edit(std::span<const std::string> args) {
    const Arguments arguments(args, {kStrictSwitch}, {"--frames", "--screenshot", "--mode", "--cage-above"});
    if (arguments.has("--help")) {
        std::cout << "usage: rgbsub edit [FILE.obj] [--frames N] [--cage-above N] [--screenshot OUT.png [--mode MODE]] [--strict]\n"
                     "Opens the editor window (needs a display) on FILE.obj, or on the default mesh;\n"
                     "'rgbsub FILE.obj [OPTIONS]' is short for 'rgbsub edit FILE.obj [OPTIONS]'.\n"
                     "  --frames N          quit after N frames once FILE is shown, printing the times\n"
                     "                      from launch to the first frame and to FILE shown\n"
                     "  --cage-above N      offer a cage that keeps the detail (as remesh makes it) when a\n"
                     "                      plain mesh opened in the window has more than N triangles\n"
                     "                      (default "
                  << app::kDenseMeshTriangles << ")\n"
                     "  --screenshot PATH   write one editor frame, panels included, as a PNG and exit\n"
                     "                      (headless through OSMesa: no display needed)\n"
                     "  --mode MODE         for the screenshot: shaded, wire, rgb, level, matcap (clay lit from\n"
                     "                      the view: shape and detail at a glance), or the file's look:\n"
                     "                      material (Kd), colours (vertex colours), checker (over the UVs),\n"
                     "                      texture (map_Kd over the UVs; Kd without one), or distance (a\n"
                     "                      cage with detail only: its distance to the dense mesh)\n"
                  << kStrictHelp;
        return exit_ok;
    }
    if (arguments.positional().size() > 1) throw UsageError("expects at most one FILE.obj");
    app::WindowLaunch launch;
    launch.file = arguments.positional().empty() ? app::default_mesh_path() : arguments.positional().front();
    // The editor repairs what it opens; --strict first makes sure FILE.obj needs no repair.
    if (arguments.has(kStrictSwitch) && launch.file) rgbio::read_mesh_file(*launch.file, read_options(arguments));
    if (arguments.has("--cage-above"))
        launch.cage_above = static_cast<std::size_t>(arguments.integer("--cage-above", 0, 0, std::numeric_limits<long>::max()));
    if (arguments.has("--frames")) launch.frames = static_cast<int>(arguments.integer("--frames", 1, 1, 1000000));
    if (const auto output = arguments.value("--screenshot")) {
        if (!launch.file) throw UsageError("--screenshot needs a FILE.obj");
        return write_screenshot(*launch.file, *output, arguments.value("--mode").value_or("shaded"));
    }
    if (std::getenv("DISPLAY") == nullptr) {
        std::cerr << "rgbsub edit: no display (DISPLAY is not set); headless alternative: rgbsub render\n";
        return exit_bad_input;
    }
    return app::run_editor_window(launch);
}

}  // namespace cli
