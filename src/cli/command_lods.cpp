// rgbsub lods IN -o OUT (--budgets T1,T2,... | --tolerances E1,E2,... | --levels L1,L2,...): a set of
// levels of detail, finest first (io/script/lod_set.h), in one glTF file (MSFT_lod) or one file per level
// (io/lod_set_files.h, which the editor's Export LODs panel uses too).
#include <iostream>
#include <optional>
#include <vector>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/mesh_io_support.h"
#include "cli/progress.h"
#include "io/base_attributes.h"
#include "io/formats/mesh_format.h"
#include "io/lod_set_files.h"
#include "io/script/lod_set.h"
#include "io/script/triangle_limit.h"

namespace cli {

namespace {

constexpr std::string_view kLodsHelp =
    "usage: rgbsub lods IN -o OUT (--budgets T1,T2,... | --tolerances E1,E2,... | --levels L1,L2,...)\n"
    "                   [--positions limit|display] [--max-triangles N] [--plain] [--strict] [--msh-binary]\n"
    "                   [--sharp-angle DEG] [--boundary edge-only|edge-and-corner] [--uv-interpolation OPTION]\n"
    "Writes a set of levels of detail of IN, LOD0 (the finest) to LODn, each the canonical mesh of its\n"
    "request, as refine and apply make it:\n"
    "  --levels L1,L2,...      each level every face at level L (0..20)\n"
    "  --budgets T1,T2,...     each level at most T triangles (the budget driver, as apply's budget line)\n"
    "  --tolerances E1,E2,...  each level within E (or E% of the bounding-box diagonal) of the Loop limit\n"
    "                          surface (of the dense mesh on a cage with detail), as refine --tolerance\n"
    "OUT.glb or OUT.gltf: one file; its node shows LOD0 and names the others through MSFT_lod, with\n"
    "MSFT_screencoverage hints from each level's error. Other extensions (.obj, .ply, .stl, .vtu, .msh):\n"
    "one file per level, OUT's stem with _LOD0, _LOD1, ... Prints each level's triangles, its error\n"
    "(the written surface against the limit surface, or the dense mesh of a cage with detail), the screen\n"
    "coverage down to which it is shown, and whether its vertices are among the finer level's.\n"
    "  --positions limit|display  write the Loop limit positions (default; a cage with detail: its\n"
    "                      detail positions), so that a vertex sits at the same point in every level and\n"
    "                      levels by --levels or --budgets nest; or the displayed ones\n"
    "--plain writes OBJ levels without the adaptive state (#rgb lines).\n";

}  // namespace

int run_lods(std::span<const std::string> args) {
    const Arguments arguments(args, {"--plain", kStrictSwitch, kMshBinarySwitch},
                              {"--output", "--budgets", "--tolerances", "--levels", "--positions", "--max-triangles",
                               kSharpAngleOption, kBoundaryOption, kUvInterpolationOption},
                              {{"-o", "--output"}});
    if (arguments.has("--help")) {
        std::cout << kLodsHelp << kMshBinaryHelp << kStrictHelp << kSharpHelp << kUvHelp;
        return exit_ok;
    }
    if (arguments.positional().size() != 1) throw UsageError("expects exactly one IN");
    const std::optional<std::string> output = arguments.value("--output");
    if (!output) throw UsageError("needs -o OUT");
    std::optional<rgbio::LodSetCriterion> criterion;
    std::string list;
    for (const auto& [option, kind] : {std::pair{"--levels", rgbio::LodSetCriterion::Levels},
                                       std::pair{"--budgets", rgbio::LodSetCriterion::Budgets},
                                       std::pair{"--tolerances", rgbio::LodSetCriterion::Tolerances}}) {
        if (const std::optional<std::string> value = arguments.value(option)) {
            if (criterion) throw UsageError("takes one of --levels, --budgets and --tolerances");
            criterion = kind;
            list = *value;
        }
    }
    if (!criterion) throw UsageError("needs --levels L1,L2,..., --budgets T1,T2,... or --tolerances E1,E2,...");
    const std::optional<std::string> positions = arguments.value("--positions");
    if (positions) parse_positions(*positions);  // a bad value is a usage error before the load
    const rgbio::MshEncoding msh = msh_encoding(arguments, *output);
    // Every level's error is measured at the tolerance criterion's samples, whatever the criterion, so
    // the default bounds memory as a tolerance request's (triangle_limit.h).
    const auto limit = static_cast<std::size_t>(arguments.integer(
        "--max-triangles", static_cast<long>(rgbio::default_triangle_limit(rgbio::MemoryUse::Tolerance)), 1, 4'000'000'000l));
    const std::string& input = arguments.positional()[0];
    const rgbio::OutputFormat format = rgbio::output_format(*output);

    // The folder, and the first file written (for glTF, the only one).
    check_output_first(format == rgbio::OutputFormat::Gltf ? *output : rgbio::lod_file_name(*output, 0));
    rgbio::LoadedAsset asset = load_input("lods", input, arguments);
    check_gltf_output_first("lods", *output, asset);
    std::vector<rgbio::ScriptLine> requests;
    try {
        requests = rgbio::lod_set_requests(*criterion, list, asset.mesh);
    } catch (const std::invalid_argument& error) {
        throw UsageError(std::string(rgbio::lod_set_option(*criterion)) + ": " + error.what());
    }
    rgbio::SaveOptions save;
    save.positions = positions ? parse_positions(*positions) : rgbio::lod_set_positions(asset.mesh);
    save.state = !arguments.has("--plain");
    save.msh = msh;
    save.attributes = asset.attributes;
    save.uvs = input_uv_layout(arguments, asset);
    print_warnings("lods", *output, rgbio::dropped_skin(save.attributes.get(), *output));
    // The sizes a request can be checked for ahead are checked for all levels before any work.
    rgbio::check_lod_set_size(asset.mesh, requests, limit);

    rgbio::LodSetOptions options;
    options.save = save;
    options.max_triangles = limit;
    options.output = *output;
    std::optional<Progress> progress;
    options.progress = [&progress](std::size_t step, std::size_t levels) {
        if (step == 0) progress.emplace("making the levels");
        if (step == levels) progress.emplace("measuring the levels' errors");
        progress->update(step, levels, step < levels ? "LOD" + std::to_string(step) : std::string());
        return true;
    };
    const rgbio::LodSet set = rgbio::make_lod_set(asset.mesh, requests, options);
    progress.reset();
    print_warnings("lods", *output, set.warnings);
    const std::vector<rgbio::LodSetLevel>& levels = set.levels;
    bool all_nested = true;
    for (std::size_t i = 0; i < levels.size(); ++i) {
        const rgbio::LodSetLevel& level = levels[i];
        std::cout << (format == rgbio::OutputFormat::Gltf ? *output : rgbio::lod_file_name(*output, i)) << ": LOD" << i << " ("
                  << level.request.text << "): " << level.mesh.num_faces() << " triangles, error " << level.error << " ("
                  << 100.0 * level.error / set.size << "% of the size), shown down to screen coverage " << level.coverage;
        if (i > 0) std::cout << (level.nested ? ", nested in LOD" : ", not nested in LOD") << i - 1;
        std::cout << '\n';
        all_nested = all_nested && (i == 0 || level.nested);
    }
    if (!all_nested)
        std::cout << "rgbsub lods: not every level's vertices are among the finer level's"
                  << (*criterion == rgbio::LodSetCriterion::Tolerances ? " (the tolerance criterion need not nest: an edge's value depends on "
                                                                        "the tolerance)"
                                                                      : "")
                  << (save.positions == rgbio::SavedPositions::Displayed && !asset.mesh.base().detail()
                          ? " (displayed positions differ between levels; --positions limit nests them)"
                          : "")
                  << '\n';
    if (save.state && format != rgbio::OutputFormat::Obj && format != rgbio::OutputFormat::Gltf)
        std::cerr << "rgbsub lods: " << *output << ": note: the adaptive state is kept only in OBJ files; these "
                  << rgbio::format_name(format) << " files are exports that rgbsub cannot refine further\n";
    return exit_ok;
}

}  // namespace cli
