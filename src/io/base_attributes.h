#pragma once
// What rides on the base mesh besides its positions: face labels and texture coordinates per base
// face, colours per base vertex, the material libraries. It is indexed by base face and base vertex,
// never by the adaptive mesh's slots, so refinement never changes it: every face of the adaptive
// mesh lies in one base face (rgb::base_face_of) and takes its labels. rgb::Mesh holds geometry only;
// the CLI and the editor keep this beside it (shared, immutable) and hand it to the savers.
//
// Colours are vertex data (rgb/values/vertex_channel.h): written at every level, and kept in the state's
// base-colours section (base_colour_state.h). Texture coordinates here are the level-0 ones; a
// refined mesh's come from its exact UV channel (base_uvs.h), and a save without one says that it
// leaves them out (dropped_attributes).
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "io/obj/loaded_mesh.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/uv_layout.h"

namespace rgbio {

struct BaseAttributes {
    BaseFaceLabels labels;
    std::vector<std::string> material_libraries;  // mtllib names as the input wrote them
    std::string library_folder;                   // the folder they are relative to (the input's), or empty
    std::vector<Material> materials;              // what they define
    // As in LoadedMesh, for the base faces' corners.
    std::vector<glm::dvec2> texcoords;
    std::vector<std::array<std::uint32_t, 3>> triangle_texcoords;  // empty, or per base face
    std::vector<glm::dvec3> colours;                               // empty, or per base vertex
    // A glTF skin (io/obj/skin.h): written to glTF at every level (io/skin_weights.h), per base vertex.
    std::shared_ptr<const Skeleton> skeleton;
    std::vector<JointInfluences> influences;
};

// The attributes of the base mesh of a loaded file, whose mesh is `mesh` (build_mesh(loaded)). A
// plain file's base faces are its triangles in order, so its own data is the base's. A file with an
// adaptive state gives its base faces' labels from the state, its colours from the state's
// base-colours section, and its texture coordinates and colours when the saved mesh is the base mesh
// itself (level 0): they are on base faces then. `folder`: the file's folder (material libraries are
// relative to it). Appends a warning for a refined file with colours but no base-colours section.
BaseAttributes base_attributes(const LoadedMesh& loaded, const rgb::Mesh& mesh, const std::string& folder,
                               std::vector<std::string>& warnings);

// A mesh file's mesh and what rides on its base.
struct LoadedAsset {
    rgb::Mesh mesh;
    std::shared_ptr<const BaseAttributes> attributes;
    std::optional<rgb::UvChannel> uvs;  // the base mesh's texture coordinates (base_uvs.h), if any
};

// read_mesh_file (any format) + build_mesh + base_attributes + base_uv_channel. Warnings are appended to *warnings if given.
LoadedAsset load_asset(const std::string& path, std::vector<std::string>* warnings = nullptr, const ReadOptions& options = {});

// Whether the adaptive mesh is its base mesh (no face refined): then texture coordinates and colours
// of the base are those of the mesh.
bool is_base_mesh(const rgb::Mesh& mesh);

// The base texture coordinate of corner `corner` of face f of a mesh at level 0, or kNoIndex.
std::uint32_t base_corner_texcoord(const rgb::Mesh& mesh, const BaseAttributes& attributes, rgb::FaceId f, int corner);

// The mtllib references for a file written into `output_folder`: as the input wrote them where
// they still lead to the same file (absolute names, or the same folder); else relative to the output
// folder where the two share their top folder (a tree moved whole keeps working), else absolute.
std::vector<std::string> library_references(const BaseAttributes& attributes, const std::string& output_folder);

// What a save of `mesh` leaves out of the attributes, one sentence each (empty when nothing).
// `exact_uvs`: the texture coordinates are written through their own channel (rgb/values/uv_layout.h).
std::vector<std::string> dropped_attributes(const rgb::Mesh& mesh, const BaseAttributes* attributes, bool exact_uvs = false);

// What a save to `path` leaves out of a skin, one sentence (empty when nothing): only glTF carries one.
std::vector<std::string> dropped_skin(const BaseAttributes* attributes, const std::string& path);

}  // namespace rgbio
