#include "cli/mesh_io_support.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "cli/commands.h"
#include "io/base_uvs.h"
#include "io/files/save_target.h"
#include "io/gltf_export.h"
#include "io/obj/obj_error.h"
#include "io/scale_check.h"
#include "io/mesh_export.h"
#include "rgb/mesh/sharp_angle.h"
#include "rgb/values/restore_state.h"

namespace cli {

void print_warnings(const char* command, const std::string& file, const std::vector<std::string>& warnings) {
    for (const std::string& warning : warnings) std::cerr << "rgbsub " << command << ": " << file << ": warning: " << warning << '\n';
}

rgbio::LoadedAsset load_input(const char* command, const std::string& file, const Arguments& arguments) {
    std::vector<std::string> warnings;
    rgbio::LoadedAsset asset = rgbio::load_asset(file, &warnings, read_options(arguments));
    print_warnings(command, file, warnings);
    rgbio::check_scale(asset.mesh.base().positions(), {rgbio::kDoubleScale}, file, "work on");
    asset.mesh = with_sharp_options(arguments, std::move(asset.mesh));
    return asset;
}

void check_output_first(const std::string& file) {
    const rgbio::SaveTarget target = rgbio::resolve_save_target(file);
    std::error_code error;
    if (!std::filesystem::is_directory(target.folder, error))
        throw rgbio::SaveError("cannot save " + file + ": its folder " + target.folder + " is not there");
    if (::access(target.folder.c_str(), W_OK | X_OK) != 0)
        throw rgbio::SaveError("cannot save " + file + ": its folder " + target.folder + " is not writable (" + std::strerror(errno) + ")");
}

void check_gltf_output_first(const char* command, const std::string& output, const rgbio::LoadedAsset& asset) {
    if (!rgbio::is_gltf_path(output)) return;
    // The subdivided surface lies in the hull of the base mesh: its positions answer for every level.
    if (const std::optional<std::string> problem = rgbio::scale_problem(asset.mesh.base().positions(), rgbio::kFloatScale))
        throw std::invalid_argument("cannot write " + output + " (glTF keeps 32-bit floats): " + *problem);
    print_warnings(command, output, rgbio::gltf_material_repairs(asset.attributes->materials));
}

void save_output(const char* command, const rgb::Mesh& mesh, const std::string& file, const rgbio::SaveOptions& save) {
    // Both writers have the exact texture coordinates of every level from the UV layout.
    std::vector<std::string> warnings = rgbio::dropped_attributes(mesh, save.attributes.get(), save.uvs != nullptr);
    for (std::string& skin : rgbio::dropped_skin(save.attributes.get(), file)) warnings.push_back(std::move(skin));
    if (mesh.base().has_sharp_features() && (save.normals || rgbio::is_gltf_path(file)))
        warnings.push_back("the normals follow the smooth Loop rules (rgb/values/limit_normals.h): at vertices on tagged creases and "
                           "corners, whose tangent masks are not implemented yet, they are approximate");
    if (rgbio::is_gltf_path(file)) {
        // What the input's scale and materials say was checked before the work (check_gltf_output_first).
        const rgbio::GltfMesh gltf = rgbio::gltf_mesh(mesh, save);
        if (std::optional<std::string> repair = rgbio::gltf_normal_repair(gltf)) warnings.push_back(std::move(*repair));
        print_warnings(command, file, warnings);
        rgbio::save_gltf(gltf, file);
        return;
    }
    print_warnings(command, file, warnings);
    // glTF exports have always been plain exports (docs/files.md); the formats added beside them say it.
    const rgbio::OutputFormat format = rgbio::output_format(file);
    if (save.state && format != rgbio::OutputFormat::Obj && format != rgbio::OutputFormat::Gltf)
        std::cerr << "rgbsub " << command << ": " << file << ": note: the adaptive state is kept only in OBJ files; this "
                  << rgbio::format_name(format) << " file is an export that rgbsub cannot refine further\n";
    rgbio::save_mesh_file(mesh, file, save);
}

rgbio::MshEncoding msh_encoding(const Arguments& arguments, const std::string& output) {
    if (!arguments.has(kMshBinarySwitch)) return rgbio::MshEncoding::Ascii;
    if (rgbio::output_format(output) != rgbio::OutputFormat::Msh)
        throw UsageError(std::string(kMshBinarySwitch) + " writes Gmsh files: it needs -o OUT.msh, not " + output);
    return rgbio::MshEncoding::Binary;
}

rgbio::ReadOptions read_options(const Arguments& arguments) { return {.strict = arguments.has(kStrictSwitch)}; }

rgb::Mesh with_sharp_options(const Arguments& arguments, rgb::Mesh mesh) {
    const std::optional<std::string> boundary = arguments.value(kBoundaryOption);
    if (!arguments.has(kSharpAngleOption) && !boundary) return mesh;
    rgb::SharpFeatures features = mesh.base().sharp_features();
    if (boundary) {
        const auto parsed = rgb::parse_boundary_interpolation(*boundary);
        if (!parsed) throw UsageError("--boundary must be 'edge-only' or 'edge-and-corner', not '" + *boundary + "'");
        features.boundary = *parsed;
    }
    if (arguments.has(kSharpAngleOption)) {
        const double degrees = arguments.number(kSharpAngleOption, 0.0);
        if (degrees < 0.0 || degrees > 180.0) throw UsageError("--sharp-angle must be between 0 and 180 degrees");
        // Later tags replace earlier ones (BaseMesh), so an edge the file tags semi-sharp becomes infinite.
        for (const rgb::EdgeSharpness& e : rgb::edges_sharper_than(mesh.base(), degrees)) features.edges.push_back(e);
    }
    if (features == mesh.base().sharp_features()) return mesh;
    return rgb::with_sharp_features(mesh, features);
}

std::shared_ptr<const rgb::UvLayout> input_uv_layout(const Arguments& arguments, const rgbio::LoadedAsset& asset) {
    std::optional<rgb::UvInterpolation> interpolation;
    if (const std::optional<std::string> value = arguments.value(kUvInterpolationOption)) {
        interpolation = rgb::parse_uv_interpolation(*value);
        if (!interpolation)
            throw UsageError("--uv-interpolation must be 'none', 'corners', 'boundaries' or 'all', not '" + *value + "'");
    }
    // Classified by the final base mesh's tags (load_input applies the crease options first).
    return rgbio::uv_layout(asset.uvs, asset.mesh, interpolation);
}

rgbio::SavedPositions parse_positions(const std::string& value) {
    if (value == "display") return rgbio::SavedPositions::Displayed;
    if (value == "limit") return rgbio::SavedPositions::Limit;
    throw UsageError("--positions must be 'display' or 'limit', not '" + value + "'");
}

}  // namespace cli
