// rgbsub apply IN.obj SCRIPT -o OUT.obj [--timings]: a script of level-of-detail edits, the
// headless twin of brush strokes.
#include <chrono>
#include <iostream>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/lod_script.h"
#include "cli/mesh_io_support.h"
#include "cli/progress.h"

namespace cli {

int run_apply(std::span<const std::string> args) {
    const std::vector<std::string> words = with_long_output_option(args);
    const Arguments arguments(words, {"--timings", "--normals", "--plain", kStrictSwitch}, {"--output", "--positions"});
    if (arguments.has("--help")) {
        std::cout << "usage: rgbsub apply IN.obj SCRIPT -o OUT.obj [--timings] [--positions display|limit] [--normals]\n"
                     "                    [--plain] [--strict]\n"
                     "Runs SCRIPT, one edit per line, then saves the adaptive mesh:\n"
                     "  level N sphere X Y Z R   set the level of detail to N inside the sphere\n"
                     "  level N                  set it everywhere\n"
                     "  budget TRIANGLES         refine/coarsen towards a triangle count\n"
                     "Blank lines and lines starting with # are skipped. --timings prints the engine time per line.\n"
                     "--plain writes an OBJ without the adaptive state (#rgb lines), for tools that dislike them.\n"
                  << kStrictHelp;
        return exit_ok;
    }
    if (arguments.positional().size() != 2) throw UsageError("expects IN.obj and SCRIPT");
    const std::optional<std::string> output = arguments.value("--output");
    if (!output) throw UsageError("needs -o OUT.obj");
    rgbio::SaveOptions save;
    save.positions = parse_positions(arguments.value("--positions").value_or("display"));
    save.normals = arguments.has("--normals");
    save.state = !arguments.has("--plain");
    const std::string& input = arguments.positional()[0];
    const std::string& script_file = arguments.positional()[1];

    return report_io_errors("apply", [&] {
        // The whole script is checked before the (possibly long) load and edits.
        const std::vector<LodEdit> script = read_lod_script(script_file);
        std::vector<std::string> warnings;
        rgb::Mesh mesh = rgbio::load_mesh(input, &warnings, read_options(arguments));
        print_warnings("apply", input, warnings);
        Progress progress("applying " + script_file);
        for (std::size_t i = 0; i < script.size(); ++i) {
            progress.update(i, script.size(), "(line " + std::to_string(script[i].line) + ")");
            const auto start = std::chrono::steady_clock::now();
            const rgb::SetLevelStats stats = apply_lod_edit(mesh, script[i]);
            const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;
            if (arguments.has("--timings"))
                std::cout << script_file << ':' << script[i].line << ": " << script[i].text << ": " << elapsed.count() << " ms, "
                          << stats.splits << " splits, " << stats.removals << " removals, " << mesh.num_faces() << " triangles\n";
        }
        rgbio::save_mesh(mesh, *output, save);
        return exit_ok;
    });
}

}  // namespace cli
