// rgbsub refine IN.obj -o OUT.obj|OUT.glb|OUT.gltf (--level N | --max-edge L | --tolerance E) [--sphere X,Y,Z,R]
// [--positions display|limit] [--sharp-angle DEG]
#include <charconv>
#include <cmath>
#include <iostream>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/mesh_io_support.h"
#include "cli/progress.h"
#include "io/script/detail_edit.h"
#include "io/script/triangle_limit.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/mesh.h"

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

// The detail a criterion option asks for, or nullopt for --level.
std::optional<rgbio::DetailEdit> detail_edit(const Arguments& arguments) {
    std::optional<rgbio::DetailEdit> edit;
    for (const auto& [option, criterion] : {std::pair{"--max-edge", rgbio::DetailCriterion::MaxEdge},
                                            std::pair{"--tolerance", rgbio::DetailCriterion::Tolerance}}) {
        const std::optional<std::string> text = arguments.value(option);
        if (!text) continue;
        const auto amount = rgbio::parse_amount(*text);
        if (!amount)
            throw UsageError(std::string(option) + " expects a positive length, or a percentage of the bounding-box diagonal like 0.5%, not '" +
                             *text + "'");
        edit = rgbio::DetailEdit{criterion, *amount, rgb::RequestKind::Set, std::nullopt};
    }
    return edit;
}

}  // namespace

int run_refine(std::span<const std::string> args) {
    const Arguments arguments(args, {"--normals", "--plain", kStrictSwitch, kMshBinarySwitch},
                              {"--output", "--level", "--max-edge", "--tolerance", "--sphere", "--positions", "--max-triangles",
                               kSharpAngleOption, kBoundaryOption, kUvInterpolationOption},
                              {{"-o", "--output"}});
    if (arguments.has("--help")) {
        std::cout << "usage: rgbsub refine IN.obj -o OUT (--level N | --max-edge L | --tolerance E) [--sphere X,Y,Z,R]\n"
                     "                     [--positions display|limit] [--normals] [--max-triangles N] [--plain] [--strict]\n"
                     "                     [--msh-binary] [--sharp-angle DEG] [--boundary edge-only|edge-and-corner] [--uv-interpolation OPTION]\n"
                     "Sets the level of detail inside the sphere (everywhere without --sphere; its coordinates are\n"
                     "those of IN.obj's base mesh), by one of:\n"
                     "  --level N       every face meeting the sphere gets level N (0.." << rgb::kMaxLevel << ")\n"
                     "  --max-edge L    no green edge (an edge of a uniform level) longer than L in the uniform mesh\n"
                     "                  of its level, as coarse as that allows (red and blue diagonals can be\n"
                     "                  longer); L in IN.obj's units, or L% of its bounding-box diagonal\n"
                     "  --tolerance E   the displayed surface within E (or E% of the diagonal) of the Loop limit\n"
                     "                  surface at its samples (between them up to 3% above E), in the smallest\n"
                     "                  mesh in which no unsplit edge could push the error over E; prints the\n"
                     "                  error reached\n"
                     "OUT.obj keeps the adaptive state, so it can be refined further; '--level 0' on it returns the\n"
                     "base mesh. Texture coordinates (by --uv-interpolation) and vertex colours (by the position\n"
                     "rules) are subdivided with the positions and saved exactly, materials kept per face.\n"
                     "--positions limit writes Loop limit positions. A request estimated (or, for\n"
                     "--max-edge and --tolerance, found) to exceed --max-triangles (default: from this machine's\n"
                     "memory) is refused and nothing is saved.\n"
                     "--plain writes an OBJ without the adaptive state (#rgb lines), for tools that dislike them.\n"
                  << kOutputHelp << kMshBinaryHelp << kStrictHelp << kSharpHelp << kUvHelp;
        return exit_ok;
    }
    if (arguments.positional().size() != 1) throw UsageError("expects exactly one IN.obj");
    const std::optional<std::string> output = arguments.value("--output");
    if (!output) throw UsageError("needs -o OUT.obj");
    const int asked = int(arguments.has("--level")) + int(arguments.has("--max-edge")) + int(arguments.has("--tolerance"));
    if (asked != 1) throw UsageError(asked == 0 ? "needs --level N, --max-edge L or --tolerance E" : "takes one of --level, --max-edge and --tolerance");
    std::optional<rgbio::DetailEdit> detail = detail_edit(arguments);
    rgb::LevelRequest request;
    request.level = static_cast<int>(arguments.integer("--level", 0, 0, rgb::kMaxLevel));
    if (arguments.has("--sphere")) request.sphere = parse_sphere(*arguments.value("--sphere"));
    if (detail) detail->sphere = request.sphere;
    const auto limit = static_cast<std::size_t>(
        arguments.integer("--max-triangles",
                          static_cast<long>(rgbio::default_triangle_limit(detail ? rgbio::memory_use(detail->criterion) : rgbio::MemoryUse::Level)),
                          1, 4'000'000'000l));
    rgbio::SaveOptions save;
    save.positions = parse_positions(arguments.value("--positions").value_or("display"));
    save.normals = arguments.has("--normals");
    save.state = !arguments.has("--plain");
    save.msh = msh_encoding(arguments, *output);
    const std::string& input = arguments.positional()[0];

    check_output_first(*output);
    rgbio::LoadedAsset asset = load_input("refine", input, arguments);
    check_gltf_output_first("refine", *output, asset);
    rgb::Mesh& mesh = asset.mesh;
    save.attributes = asset.attributes;
    save.uvs = input_uv_layout(arguments, asset);
    if (detail) {
        rgbio::DetailOutcome outcome;
        {
            Progress progress("refining");
            progress.update(0, 1, detail->criterion == rgbio::DetailCriterion::MaxEdge ? "to the edge length" : "to the tolerance");
            outcome = rgbio::apply_detail_edit(mesh, *detail, limit);
        }
        if (outcome.report.level_cap_bound)
            std::cerr << "rgbsub refine: wanted detail stops at the maximum level " << rgb::kMaxLevel << '\n';
        if (outcome.reached_error)
            std::cout << "rgbsub refine: " << mesh.num_faces() << " triangles, maximum error " << *outcome.reached_error
                      << " (tolerance " << rgbio::world_amount(mesh, detail->amount) << ")\n";
    } else {
        rgbio::check_request_size(mesh, request, limit);
        Progress progress("refining");
        progress.update(0, 1, "to level " + std::to_string(request.level));
        rgb::apply_request(mesh, request);
    }
    save_output("refine", mesh, *output, save);
    return exit_ok;
}

}  // namespace cli
