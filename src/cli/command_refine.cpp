// rgbsub refine IN.obj -o OUT.obj --level N [--sphere X,Y,Z,R] [--positions display|limit]
#include <charconv>
#include <cmath>
#include <iostream>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/mesh_io_support.h"
#include "cli/progress.h"
#include "rgb/refine.h"

namespace cli {

namespace {

constexpr long kMaxLevel = 20;

rgb::Region parse_sphere(const std::string& text) {
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
    return rgb::Region::sphere({values[0], values[1], values[2]}, values[3]);
}

}  // namespace

int run_refine(std::span<const std::string> args) {
    const std::vector<std::string> words = with_long_output_option(args);
    const Arguments arguments(words, {"--normals", "--plain", kStrictSwitch}, {"--output", "--level", "--sphere", "--positions"});
    if (arguments.has("--help")) {
        std::cout << "usage: rgbsub refine IN.obj -o OUT.obj --level N [--sphere X,Y,Z,R] [--positions display|limit]\n"
                     "                     [--normals] [--plain] [--strict]\n"
                     "Sets the level of detail to N inside the sphere (everywhere without --sphere): faces below N\n"
                     "are refined, vertices above N removed where removable. OUT.obj keeps the adaptive state, so\n"
                     "it can be refined further; '--level 0' on it returns the base mesh. --positions limit writes\n"
                     "Loop limit positions where the mesh holds a vertex's ring (displayed ones elsewhere).\n"
                     "--plain writes an OBJ without the adaptive state (#rgb lines), for tools that dislike them.\n"
                  << kStrictHelp;
        return exit_ok;
    }
    if (arguments.positional().size() != 1) throw UsageError("expects exactly one IN.obj");
    const std::optional<std::string> output = arguments.value("--output");
    if (!output) throw UsageError("needs -o OUT.obj");
    if (!arguments.has("--level")) throw UsageError("needs --level N");
    const int level = static_cast<int>(arguments.integer("--level", 0, 0, kMaxLevel));
    const rgb::Region region = arguments.has("--sphere") ? parse_sphere(*arguments.value("--sphere")) : rgb::Region::everywhere();
    rgbio::SaveOptions save;
    save.positions = parse_positions(arguments.value("--positions").value_or("display"));
    save.normals = arguments.has("--normals");
    save.state = !arguments.has("--plain");
    const std::string& input = arguments.positional()[0];

    return report_io_errors("refine", [&] {
        std::vector<std::string> warnings;
        rgb::Mesh mesh = rgbio::load_mesh(input, &warnings, read_options(arguments));
        print_warnings("refine", input, warnings);
        {
            Progress progress("refining");
            progress.update(0, 1, "to level " + std::to_string(level));
            rgb::set_level(mesh, region, level);
        }
        const rgbio::SaveReport report = rgbio::save_mesh(mesh, *output, save);
        if (report.limit_fallbacks > 0)
            std::cerr << "rgbsub refine: " << report.limit_fallbacks
                      << " vertices written at their displayed position: their limit needs a ring the mesh does not hold\n";
        return exit_ok;
    });
}

}  // namespace cli
