// rgbsub refine IN.obj -o OUT.obj|OUT.glb|OUT.gltf --level N [--sphere X,Y,Z,R] [--positions display|limit]
// [--sharp-angle DEG]
#include <charconv>
#include <cmath>
#include <iostream>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/mesh_io_support.h"
#include "cli/progress.h"
#include "io/triangle_limit.h"
#include "rgb/mesh.h"
#include "rgb/requests.h"

namespace cli {

namespace {

rgb::Sphere parse_sphere(const std::string& text) {
    double values[4];
    const char* p = text.data();
    const char* end = text.data() + text.size();
    for (int i = 0; i < 4; ++i) {
        const auto [next, ec] = std::from_chars(p, end, values[i]);
        const bool separator_ok = i == 3 ? next == end : next != end && *next == ',';
        if (ec != std::errc() || !separator_ok || !std::isfinite(values[i]))
            throw UsageError("--sphere expects X,Y,Z,R (four numbers separated by commas), not '" + text + "'");
        p = next + 1;
    }
    if (values[3] <= 0) throw UsageError("--sphere radius must be positive");
    return rgb::Sphere{{values[0], values[1], values[2]}, values[3]};
}

}  // namespace

int run_refine(std::span<const std::string> args) {
    const Arguments arguments(args, {"--normals", "--plain", kStrictSwitch},
                              {"--output", "--level", "--sphere", "--positions", "--max-triangles", kSharpAngleOption,
                               kBoundaryOption},
                              {{"-o", "--output"}});
    if (arguments.has("--help")) {
        std::cout << "usage: rgbsub refine IN.obj -o OUT --level N [--sphere X,Y,Z,R] [--positions display|limit]\n"
                     "                     [--normals] [--max-triangles N] [--plain] [--strict] [--sharp-angle DEG]\n"
                     "                     [--boundary edge-only|edge-and-corner]\n"
                     "Sets the level of detail to N (0.." << rgb::kMaxLevel << ") inside the sphere (everywhere without\n"
                     "--sphere; its coordinates are those of IN.obj's base mesh): every face meeting it gets level N.\n"
                     "OUT.obj keeps the adaptive state, so it can be refined further; '--level 0' on it returns the\n"
                     "base mesh. --positions limit writes Loop limit positions. A request estimated to exceed\n"
                     "--max-triangles (default: from this machine's memory) is refused before it runs.\n"
                     "--plain writes an OBJ without the adaptive state (#rgb lines), for tools that dislike them.\n"
                  << kOutputHelp << kStrictHelp << kSharpHelp;
        return exit_ok;
    }
    if (arguments.positional().size() != 1) throw UsageError("expects exactly one IN.obj");
    const std::optional<std::string> output = arguments.value("--output");
    if (!output) throw UsageError("needs -o OUT.obj");
    if (!arguments.has("--level")) throw UsageError("needs --level N");
    rgb::LevelRequest request;
    request.level = static_cast<int>(arguments.integer("--level", 0, 0, rgb::kMaxLevel));
    if (arguments.has("--sphere")) request.sphere = parse_sphere(*arguments.value("--sphere"));
    const auto limit = static_cast<std::size_t>(
        arguments.integer("--max-triangles", static_cast<long>(rgbio::default_triangle_limit()), 1, 4'000'000'000l));
    rgbio::SaveOptions save;
    save.positions = parse_positions(arguments.value("--positions").value_or("display"));
    save.normals = arguments.has("--normals");
    save.state = !arguments.has("--plain");
    const std::string& input = arguments.positional()[0];

    rgbio::LoadedAsset asset = load_input("refine", input, arguments);
    rgb::Mesh& mesh = asset.mesh;
    save.attributes = asset.attributes;
    rgbio::check_request_size(mesh, request, limit);
    {
        Progress progress("refining");
        progress.update(0, 1, "to level " + std::to_string(request.level));
        rgb::apply_request(mesh, request);
    }
    save_output("refine", mesh, *output, save);
    return exit_ok;
}

}  // namespace cli
