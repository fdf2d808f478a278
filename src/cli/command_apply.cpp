// rgbsub apply IN.obj SCRIPT -o OUT.obj|OUT.glb|OUT.gltf [--timings]: a script of level-of-detail edits, the
// headless twin of brush strokes.
#include <algorithm>
#include <chrono>
#include <iostream>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/mesh_io_support.h"
#include "cli/progress.h"
#include "io/script/lod_script.h"
#include "io/script/triangle_limit.h"
#include "rgb/mesh/mesh.h"

namespace cli {

namespace {

double percentile(std::vector<double> values, double p) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    return values[static_cast<std::size_t>(p * static_cast<double>(values.size() - 1) + 0.5)];
}

// The path of the script's lines that costs the most memory per triangle: it sets the default limit.
rgbio::MemoryUse dearest_use(const std::vector<rgbio::ScriptLine>& script) {
    rgbio::MemoryUse dearest = rgbio::MemoryUse::Level;
    for (const rgbio::ScriptLine& line : script) {
        rgbio::MemoryUse use = rgbio::MemoryUse::Level;
        if (const auto* detail = std::get_if<rgbio::DetailEdit>(&line.edit)) use = rgbio::memory_use(detail->criterion);
        if (std::holds_alternative<rgbio::BudgetEdit>(line.edit)) use = rgbio::MemoryUse::Budget;
        if (rgbio::bytes_per_triangle(use) > rgbio::bytes_per_triangle(dearest)) dearest = use;
    }
    return dearest;
}

}  // namespace

int run_apply(std::span<const std::string> args) {
    const Arguments arguments(args, {"--timings", "--normals", "--plain", kStrictSwitch, kMshBinarySwitch},
                              {"--output", "--positions", "--max-triangles", kSharpAngleOption, kBoundaryOption,
                               kUvInterpolationOption},
                              {{"-o", "--output"}});
    if (arguments.has("--help")) {
        std::cout << "usage: rgbsub apply IN.obj SCRIPT -o OUT [--timings] [--positions display|limit] [--normals]\n"
                     "                    [--max-triangles N] [--plain] [--strict] [--msh-binary] [--sharp-angle DEG]\n"
                     "                    [--boundary edge-only|edge-and-corner] [--uv-interpolation OPTION]\n"
                     "Runs SCRIPT, one edit per line, then saves the adaptive mesh. Coordinates are those of IN.obj's\n"
                     "base mesh.\n"
                     "  level N [sphere X Y Z R]     set the level of detail to N in the sphere (everywhere without one)\n"
                     "  refine N [sphere X Y Z R]    at least level N there\n"
                     "  coarsen N [sphere X Y Z R]   at most level N there\n"
                     "  budget TRIANGLES             refine the longest edges up to a triangle count, or trim to it\n"
                     "  max-edge L [sphere X Y Z R]  no green edge (an edge of a uniform level) longer than L (or L% of\n"
                     "                               the bounding-box diagonal) in the uniform mesh of its level, as\n"
                     "                               coarse as that allows; red and blue diagonals can be longer\n"
                     "  tolerance E [sphere X Y Z R] the displayed surface within E (or E%) of the Loop limit surface at\n"
                     "                               its samples (between them up to 3% above E), in the smallest mesh\n"
                     "                               in which no unsplit edge could push the error over E; prints the\n"
                     "                               error reached\n"
                     "  brush refine|coarsen|set LEVEL RADIUS [FALLOFF]   the brush for the dab lines that follow\n"
                     "  dab X Y Z [VX VY VZ]         one dab (with a view direction: facing, connected faces only)\n"
                     "      [mirror x|y|z|xy|...]    and its mirror images across those planes (x = 0, ...)\n"
                     "Blank lines and lines starting with # are skipped. --timings prints the engine time per line,\n"
                     "and for the dabs their count and the engine time per dab (p50, p95).\n"
                     "--plain writes an OBJ without the adaptive state (#rgb lines), for tools that dislike them.\n"
                  << kOutputHelp << kMshBinaryHelp << kStrictHelp << kSharpHelp << kUvHelp;
        return exit_ok;
    }
    if (arguments.positional().size() != 2) throw UsageError("expects IN.obj and SCRIPT");
    const std::optional<std::string> output = arguments.value("--output");
    if (!output) throw UsageError("needs -o OUT.obj");
    rgbio::SaveOptions save;
    save.positions = parse_positions(arguments.value("--positions").value_or("display"));
    save.normals = arguments.has("--normals");
    save.state = !arguments.has("--plain");
    save.msh = msh_encoding(arguments, *output);
    const std::string& input = arguments.positional()[0];
    const std::string& script_file = arguments.positional()[1];

    // The whole script is checked before the (possibly long) load and edits.
    const std::vector<rgbio::ScriptLine> script = rgbio::read_lod_script(script_file);
    const auto limit = static_cast<std::size_t>(
        arguments.integer("--max-triangles", static_cast<long>(rgbio::default_triangle_limit(dearest_use(script))), 1, 4'000'000'000l));
    check_output_first(*output);
    rgbio::LoadedAsset asset = load_input("apply", input, arguments);
    check_gltf_output_first("apply", *output, asset);
    rgb::Mesh& mesh = asset.mesh;
    save.attributes = asset.attributes;
    save.uvs = input_uv_layout(arguments, asset);
    Progress progress("applying " + script_file);
    rgbio::ScriptRunner runner(limit);
    std::vector<double> dab_ms;
    rgb::RequestStats dab_stats;
    for (std::size_t i = 0; i < script.size(); ++i) {
        const rgbio::ScriptLine& line = script[i];
        progress.update(i, script.size(), "(line " + std::to_string(line.line) + ")");
        if (const auto* request = std::get_if<rgb::LevelRequest>(&line.edit)) rgbio::check_request_size(mesh, *request, limit);
        const auto* dab = std::get_if<rgbio::DabEdit>(&line.edit);
        if (dab) rgbio::check_request_size(mesh, rgb::dab_request(mesh, runner.dab(*dab)), limit);
        if (const auto* budget = std::get_if<rgbio::BudgetEdit>(&line.edit)) rgbio::check_budget_size(budget->triangles, limit);
        const auto start = std::chrono::steady_clock::now();
        const rgb::RequestStats stats = runner.run(mesh, line);
        const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;
        if (stats.level_cap_bound)
            std::cerr << "rgbsub apply: " << script_file << ':' << line.line << ": wanted detail stops at the maximum level "
                      << rgb::kMaxLevel << '\n';
        if (const std::optional<double> error = runner.reached_error())
            std::cout << script_file << ':' << line.line << ": " << line.text << ": maximum error " << *error << ", "
                      << mesh.num_faces() << " triangles\n";
        if (dab) {
            dab_ms.push_back(elapsed.count());
            dab_stats += stats;
        } else if (arguments.has("--timings") && !std::holds_alternative<rgbio::BrushEdit>(line.edit)) {
            std::cout << script_file << ':' << line.line << ": " << line.text << ": " << elapsed.count() << " ms, "
                      << stats.splits << " splits, " << stats.removals << " removals, " << mesh.num_faces() << " triangles\n";
        }
    }
    if (arguments.has("--timings") && !dab_ms.empty())
        std::cout << script_file << ": " << dab_ms.size() << " dabs: engine per dab p50 " << percentile(dab_ms, 0.5)
                  << " ms p95 " << percentile(dab_ms, 0.95) << " ms, " << dab_stats.splits << " splits, " << dab_stats.removals
                  << " removals, " << mesh.num_faces() << " triangles\n";
    save_output("apply", mesh, *output, save);
    return exit_ok;
}

}  // namespace cli
