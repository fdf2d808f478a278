// rgbsub lods IN -o OUT (--budgets T1,T2,... | --tolerances E1,E2,... | --levels L1,L2,...): a set of
// levels of detail, finest first (io/script/lod_set.h), in one glTF file (MSFT_lod) or one file per level.
#include <iostream>
#include <optional>
#include <vector>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/mesh_io_support.h"
#include "cli/progress.h"
#include "io/formats/format_writers.h"
#include "io/gltf_export.h"
#include "io/mesh_export.h"
#include "io/script/lod_set.h"
#include "io/script/triangle_limit.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/surface_error.h"

namespace cli {

namespace {

// The positions a level is written with, live vertices in slot order, and a slot's written position
// (for the error of the written surface).
struct WrittenLevel {
    std::size_t triangles = 0;
    std::vector<glm::dvec3> positions;
    rgbio::GltfMesh gltf;  // for a glTF set: the level, written with the others at the end
};

std::vector<glm::dvec3> by_slot(const rgb::Mesh& mesh, const std::vector<glm::dvec3>& positions) {
    std::vector<glm::dvec3> out(mesh.vertex_capacity());
    std::size_t k = 0;
    for (rgb::VertexId v : mesh.vertices()) out[v.idx] = positions[k++];
    return out;
}

constexpr std::string_view kLodsHelp =
    "usage: rgbsub lods IN -o OUT (--budgets T1,T2,... | --tolerances E1,E2,... | --levels L1,L2,...)\n"
    "                   [--positions limit|display] [--max-triangles N] [--plain] [--strict]\n"
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
    const Arguments arguments(args, {"--plain", kStrictSwitch},
                              {"--output", "--budgets", "--tolerances", "--levels", "--positions", "--max-triangles",
                               kSharpAngleOption, kBoundaryOption, kUvInterpolationOption},
                              {{"-o", "--output"}});
    if (arguments.has("--help")) {
        std::cout << kLodsHelp << kStrictHelp << kSharpHelp << kUvHelp;
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
        throw UsageError(std::string(*criterion == rgbio::LodSetCriterion::Levels    ? "--levels"
                                     : *criterion == rgbio::LodSetCriterion::Budgets ? "--budgets"
                                                                                      : "--tolerances") +
                         ": " + error.what());
    }
    rgbio::SaveOptions save;
    // Limit positions put a vertex at the same point in every level; a cage's detail positions are
    // the same in every level too, and are the surface it carries.
    save.positions = positions ? parse_positions(*positions)
                               : (asset.mesh.base().detail() ? rgbio::SavedPositions::Displayed : rgbio::SavedPositions::Limit);
    save.state = !arguments.has("--plain");
    save.attributes = asset.attributes;
    save.uvs = input_uv_layout(arguments, asset);
    print_warnings("lods", *output, rgbio::dropped_skin(save.attributes.get(), *output));
    // The sizes a request can be checked for ahead are checked for all levels before any work.
    for (const rgbio::ScriptLine& request : requests) {
        if (const auto* level = std::get_if<rgb::LevelRequest>(&request.edit)) rgbio::check_request_size(asset.mesh, *level, limit);
        if (const auto* budget = std::get_if<rgbio::BudgetEdit>(&request.edit)) rgbio::check_budget_size(budget->triangles, limit);
    }

    const double size = rgb::bounding_box_diagonal(asset.mesh.base());
    std::vector<WrittenLevel> levels;
    std::vector<rgb::Mesh> meshes;  // kept for the errors, measured for all levels at once
    meshes.reserve(requests.size());
    {
        Progress progress("making the levels");
        for (std::size_t i = 0; i < requests.size(); ++i) {
            progress.update(i, requests.size(), "LOD" + std::to_string(i));
            const rgb::Mesh& mesh = meshes.emplace_back(rgbio::lod_set_level(asset.mesh, requests[i], limit));
            WrittenLevel level;
            level.triangles = mesh.num_faces();
            if (format == rgbio::OutputFormat::Gltf) {
                level.gltf = rgbio::gltf_mesh(mesh, save);
                if (const std::optional<std::string> repair = rgbio::gltf_normal_repair(level.gltf))
                    print_warnings("lods", *output, {"LOD" + std::to_string(i) + ": " + *repair});
                level.positions = level.gltf.positions;
            } else {
                rgbio::ExportMesh flat = rgbio::export_mesh(mesh, save);
                level.positions = flat.positions;
                const std::string file = rgbio::lod_file_name(*output, i);
                if (format == rgbio::OutputFormat::Obj) {
                    rgbio::save_mesh(mesh, file, save);
                } else {
                    rgbio::save_export_mesh(flat, file, format);
                }
            }
            levels.push_back(std::move(level));
        }
    }
    std::vector<bool> nested(levels.size(), false);
    for (std::size_t i = 1; i < levels.size(); ++i) nested[i] = rgbio::positions_nested(levels[i].positions, levels[i - 1].positions);
    std::vector<double> errors;
    {
        Progress progress("measuring the levels' errors");
        std::vector<const rgb::Mesh*> measured;
        std::vector<std::vector<glm::dvec3>> corners;
        for (std::size_t i = 0; i < levels.size(); ++i) {
            measured.push_back(&meshes[i]);
            corners.push_back(by_slot(meshes[i], levels[i].positions));
        }
        for (const rgb::SurfaceError& error : rgb::surface_errors_at(measured, corners)) errors.push_back(error.max_error);
    }
    const std::vector<double> coverage = rgbio::switch_coverage(errors, size);
    if (format == rgbio::OutputFormat::Gltf) {
        std::vector<rgbio::GltfMesh> meshes;
        for (WrittenLevel& level : levels) meshes.push_back(std::move(level.gltf));
        rgbio::save_gltf_lods(meshes, coverage, *output);
    }
    bool all_nested = true;
    for (std::size_t i = 0; i < levels.size(); ++i) {
        std::cout << (format == rgbio::OutputFormat::Gltf ? *output : rgbio::lod_file_name(*output, i)) << ": LOD" << i << " ("
                  << requests[i].text << "): " << levels[i].triangles << " triangles, error " << errors[i] << " ("
                  << 100.0 * errors[i] / size << "% of the size), shown down to screen coverage " << coverage[i];
        if (i > 0) std::cout << (nested[i] ? ", nested in LOD" : ", not nested in LOD") << i - 1;
        std::cout << '\n';
        all_nested = all_nested && (i == 0 || nested[i]);
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
