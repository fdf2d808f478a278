#include "io/base_attributes.h"

#include "io/base_uvs.h"

#include <algorithm>
#include <filesystem>
#include <iterator>

#include "io/formats/mesh_format.h"
#include "io/materials/material_library.h"
#include "io/mesh_file.h"
#include "io/mesh_reader.h"
#include "io/obj/obj_error.h"
#include "io/obj/printable_text.h"
#include "io/obj_reader.h"
#include "rgb/mesh/face_location.h"

namespace rgbio {

namespace {

// The loaded file's own per-triangle labels, which are per base face for a plain file.
BaseFaceLabels file_labels(const LoadedMesh& loaded) {
    return {loaded.face_materials, loaded.face_groups, loaded.face_objects, loaded.face_smoothing_groups};
}

// A level-0 saved file's corner texture coordinates moved from its faces (slot i is triangle i) to
// the base faces they are.
void base_texcoords_of_faces(const LoadedMesh& loaded, const rgb::Mesh& mesh, BaseAttributes& attributes) {
    attributes.texcoords = loaded.texcoords;
    constexpr std::array<std::uint32_t, 3> kNone{kNoIndex, kNoIndex, kNoIndex};
    attributes.triangle_texcoords.assign(mesh.base().num_faces(), kNone);
    std::size_t slot = 0;
    for (rgb::FaceId f : mesh.faces()) {
        const std::uint32_t b = rgb::base_face_of(mesh, f);
        const rgb::Triangle& base_face = mesh.base().face(b);
        auto& corners = attributes.triangle_texcoords[b];
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k)
                if (base_face[k] == mesh.face_vertices(f)[c].idx) corners[k] = loaded.triangle_texcoords[slot][c];
        ++slot;
    }
}

}  // namespace

bool is_base_mesh(const rgb::Mesh& mesh) {
    // Each base face holds at least one face, and exactly one only while it is not refined.
    return mesh.num_faces() == mesh.base().num_faces();
}

BaseAttributes base_attributes(const LoadedMesh& loaded, const rgb::Mesh& mesh, const std::string& folder,
                               std::vector<std::string>& warnings) {
    BaseAttributes attributes;
    attributes.material_libraries = loaded.material_libraries;
    attributes.library_folder = folder;
    attributes.materials = loaded.materials;
    if (!loaded.adaptive) {
        attributes.labels = file_labels(loaded);
        attributes.texcoords = loaded.texcoords;
        attributes.triangle_texcoords = loaded.triangle_texcoords;
        attributes.colours = loaded.colours;
        attributes.skeleton = loaded.skeleton;
        attributes.influences = loaded.influences;
        return attributes;
    }
    attributes.labels = loaded.adaptive_labels;
    if (is_base_mesh(mesh) && !loaded.triangle_texcoords.empty()) base_texcoords_of_faces(loaded, mesh, attributes);
    // A refined mesh's UVs go through its base-uvs section (base_uvs.h), which warns without one.
    if (!loaded.base_colours.empty()) {
        attributes.colours = loaded.base_colours;
    } else if (is_base_mesh(mesh)) {
        // The base vertices are the first v lines, in base order.
        attributes.colours = loaded.colours;
    } else if (!loaded.colours.empty()) {
        warnings.push_back("ignored the file's vertex colours: the file is a refined mesh whose rgbsub state has no base-colours "
                           "section (written by another program or an older rgbsub), so they cannot be put back on its base mesh");
    }
    return attributes;
}

LoadedAsset load_asset(const std::string& path, std::vector<std::string>* warnings, const ReadOptions& options) {
    LoadedMesh loaded = read_mesh_file(path, options);
    std::vector<std::string> messages = std::move(loaded.warnings);
    LoadedAsset asset{build_mesh(loaded), nullptr, std::nullopt};
    asset.attributes = std::make_shared<const BaseAttributes>(
        base_attributes(loaded, asset.mesh, std::filesystem::path(path).parent_path().string(), messages));
    asset.uvs = base_uv_channel(loaded, asset.mesh, messages);
    if (warnings) warnings->insert(warnings->end(), messages.begin(), messages.end());
    return asset;
}

std::uint32_t base_corner_texcoord(const rgb::Mesh& mesh, const BaseAttributes& attributes, rgb::FaceId f, int corner) {
    if (attributes.triangle_texcoords.empty()) return kNoIndex;
    const std::uint32_t b = rgb::base_face_of(mesh, f);
    const rgb::Triangle& base_face = mesh.base().face(b);
    for (int k = 0; k < 3; ++k)
        if (base_face[k] == mesh.face_vertices(f)[corner].idx) return attributes.triangle_texcoords[b][k];
    return kNoIndex;
}

namespace {
bool has_control_byte(std::string_view text) {
    return std::any_of(text.begin(), text.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
}
}  // namespace

std::vector<std::string> library_references(const BaseAttributes& attributes, const std::string& output_folder) {
    namespace fs = std::filesystem;
    std::vector<std::string> references;
    const fs::path from = fs::absolute(attributes.library_folder.empty() ? "." : attributes.library_folder).lexically_normal();
    const fs::path to = fs::absolute(output_folder.empty() ? "." : output_folder).lexically_normal();
    for (const std::string& written : attributes.material_libraries) {
        const fs::path target = resolve_file_reference(written, from);
        // Relative where the two share a top folder (a project tree moved as a whole keeps working),
        // absolute across unrelated places.
        const bool related = std::next(target.begin()) != target.end() && std::next(to.begin()) != to.end() &&
                             *std::next(target.begin()) == *std::next(to.begin());
        const std::string moved = related ? target.lexically_relative(to).generic_string() : target.generic_string();
        // mtllib names are split at blanks: a path with one cannot be written.
        const bool keep = from == to || fs::path(written).is_absolute() || moved.empty() ||
                          moved.find_first_of(" \t") != std::string::npos;
        std::string reference = keep ? written : moved;
        // A line break (or CR, form feed, vertical tab...) in a folder's name would end the line and
        // start another: the absolute path where that has none, else the save is refused.
        if (has_control_byte(reference)) reference = target.generic_string();
        if (has_control_byte(reference))
            throw SaveError("cannot write the material library " + quoted_file_text(reference, 200) +
                            " into an mtllib line: its path holds a line break or another control character");
        references.push_back(std::move(reference));
    }
    return references;
}

std::vector<std::string> dropped_attributes(const rgb::Mesh& mesh, const BaseAttributes* attributes, bool exact_uvs) {
    std::vector<std::string> dropped;
    if (!attributes || is_base_mesh(mesh)) return dropped;
    if (!exact_uvs && !attributes->triangle_texcoords.empty())
        dropped.push_back("the texture coordinates (vt) are not written: the mesh is refined, and without the file's UV "
                          "layout only their level-0 values are known");
    return dropped;
}

std::vector<std::string> dropped_skin(const BaseAttributes* attributes, const std::string& path) {
    if (!attributes || !attributes->skeleton || output_format(path) == OutputFormat::Gltf) return {};
    return {"the skin (joints and their weights) is not written: only glTF files carry one"};
}

}  // namespace rgbio
