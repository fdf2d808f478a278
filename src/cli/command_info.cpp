// rgbsub info FILE.obj: the loader's validation report and the mesh's statistics.
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/mesh_io_support.h"
#include "cli/mesh_summary.h"
#include "io/base_attributes.h"
#include "io/base_uvs.h"
#include "io/mesh_file.h"
#include "io/mesh_reader.h"
#include "rgb/mesh/detail_positions.h"

namespace cli {

namespace {

// What rides on the mesh besides positions, one line each, only what the file has; texture
// coordinates and colours as the other commands keep them (`attributes`, `uvs`: what load_asset
// makes), so that a file's UVs are not "there" here and dropped by refine.
void print_attributes(std::ostream& out, const rgbio::LoadedMesh& loaded, const rgbio::BaseAttributes& attributes,
                      const std::optional<rgb::UvChannel>& uvs) {
    if (!loaded.triangle_texcoords.empty()) {
        if (uvs)
            out << "texture coordinates: " << loaded.texcoords.size() << " (per corner)\n";
        else
            out << "texture coordinates: " << loaded.texcoords.size() << " in the file, dropped (see the warnings)\n";
    }
    if (!loaded.colours.empty()) out << "vertex colours: " << (attributes.colours.empty() ? "in the file, ignored (see the warnings)" : "yes") << '\n';
    if (!loaded.face_materials.empty())
        out << "materials: " << loaded.face_materials.names.size() << " used, " << loaded.materials.size()
            << " defined in the material libraries\n";
    if (!loaded.face_groups.empty()) out << "groups: " << loaded.face_groups.names.size() << '\n';
    if (!loaded.face_objects.empty()) out << "objects: " << loaded.face_objects.names.size() << '\n';
}

// The base mesh's crease and corner tags, when it has any.
void print_sharp_features(std::ostream& out, const rgb::BaseMesh& base) {
    const rgb::SharpFeatures& f = base.sharp_features();
    if (f == rgb::SharpFeatures{}) return;
    std::size_t infinite = 0, single_face_corners = 0;
    for (const rgb::EdgeSharpness& e : f.edges) infinite += e.sharpness >= rgb::kInfiniteSharpness;
    for (std::uint32_t v = 0; v < base.num_vertices(); ++v)
        single_face_corners += base.is_boundary_vertex(v) && base.valence(v) == 2;
    out << "sharp edges: " << f.edges.size() << " (" << infinite << " infinitely sharp, " << f.edges.size() - infinite
        << " semi-sharp)\n";
    out << "corners: " << f.corners.size() << " tagged";
    if (f.boundary == rgb::BoundaryInterpolation::EdgeAndCorner)
        out << ", and " << single_face_corners << " boundary vertices with a single face";
    out << "\nboundary interpolation: " << rgb::boundary_interpolation_name(f.boundary) << '\n';
}

// Where a cage's detail came from and how far it is stored, when it has any.
void print_detail(std::ostream& out, const rgb::BaseMesh& base) {
    const rgb::DetailPositions* detail = base.detail();
    if (!detail) return;
    const rgb::DetailOrigin& origin = detail->origin();
    out << "detail: from " << (origin.source.empty() ? std::string("an unnamed surface") : origin.source) << " ("
        << origin.source_triangles << " triangles), stored to level";
    if (detail->coarsest_level() == detail->finest_level())
        out << ' ' << detail->finest_level();
    else
        out << "s " << detail->coarsest_level() << ".." << detail->finest_level()
            << " (each base face its own, each base edge its coarser face's)";
    out << ", " << rgb::DetailPositions::num_points(base, detail->face_levels())
        << " points; finer levels interpolate them linearly (inside a face its grid triangle, on a base edge its two samples)\n";
    out << "detail points on the nearest point of the surface (no ray hit along the limit normal): " << origin.nearest_points << '\n';
}

}  // namespace

int run_info(std::span<const std::string> args) {
    const Arguments arguments(args, {kStrictSwitch}, {kSharpAngleOption, kBoundaryOption});
    if (arguments.has("--help")) {
        std::cout << "usage: rgbsub info FILE.obj [--strict] [--sharp-angle DEG] [--boundary edge-only|edge-and-corner]\n"
                     "Validates FILE.obj as rgbsub loads it (fixes are reported as warnings, problems as errors\n"
                     "naming the line) and prints V, E, F, boundary loops, Euler characteristic, the\n"
                     "triangles per colour and per level, and the crease tags (sharp edges, corners).\n"
                  << kStrictHelp << kSharpHelp;
        return exit_ok;
    }
    if (arguments.positional().size() != 1) throw UsageError("expects exactly one FILE.obj");
    const std::string& file = arguments.positional()[0];
    const rgbio::LoadedMesh loaded = rgbio::read_mesh_file(file, read_options(arguments));
    // A saved file's adaptive mesh is summarized where it is unless options retag it: copying millions
    // of faces costs time.
    const bool retag = arguments.has(kSharpAngleOption) || arguments.value(kBoundaryOption).has_value();
    const std::optional<rgb::Mesh> copy =
        loaded.adaptive && !retag ? std::nullopt : std::optional<rgb::Mesh>(with_sharp_options(arguments, rgbio::build_mesh(loaded)));
    const rgb::Mesh& mesh = copy ? *copy : *loaded.adaptive;
    // The warnings the other commands print on reading this file (rgbio::load_asset's).
    std::vector<std::string> warnings = loaded.warnings;
    const rgbio::BaseAttributes attributes =
        rgbio::base_attributes(loaded, mesh, std::filesystem::path(file).parent_path().string(), warnings);
    const std::optional<rgb::UvChannel> uvs = rgbio::base_uv_channel(loaded, mesh, warnings);
    std::cout << file << ": valid" << (warnings.empty() ? "" : " after fixes") << '\n';
    for (const std::string& warning : warnings) std::cout << "warning: " << warning << '\n';
    std::cout << "adaptive state: " << (loaded.adaptive ? "restored from the file's #rgb lines" : "none (base mesh)") << '\n';
    print_attributes(std::cout, loaded, attributes, uvs);
    print_sharp_features(std::cout, mesh.base());
    print_detail(std::cout, mesh.base());
    print_summary(std::cout, summarize(mesh));
    print_quality(std::cout, mesh);
    return exit_ok;
}

}  // namespace cli
