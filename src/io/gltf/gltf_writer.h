#pragma once
// Folder io/gltf (glTF 2.0 writing): includes io/obj, io/files and the core.
// glTF 2.0 export (through tinygltf) for pipelines that want a standard mesh: positions, normals,
// vertex colours, texture coordinates, one primitive per material, and materials with a base colour or a base
// colour texture (the .mtl's map_Kd image, referenced by a path relative to the output). Written as
// `.glb` (binary container) or `.gltf` (JSON with the buffer embedded as a data URI), atomically.
//
// glTF keeps attributes per vertex, so each (vertex, texture coordinate) pair of a corner becomes one
// glTF vertex, numbered in order of first use by the triangles; glTF's texture origin is the top
// left, so v is written as 1 - v. Positions, normals, colours and texture coordinates are written as
// 32-bit floats (glTF allows no doubles for them).
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "io/obj/loaded_mesh.h"

namespace rgbio {

struct GltfMesh {
    std::vector<glm::dvec3> positions;
    std::vector<glm::dvec3> normals;  // empty, or one per position (normalized when written)
    std::vector<glm::dvec3> colours;  // empty, or one per position: COLOR_0 (RGB, as floats)
    std::vector<rgb::Triangle> triangles;
    // As in LoadedMesh: a table, and per triangle corner an index into it or kNoIndex (written as 0, 0).
    std::vector<glm::dvec2> texcoords;
    std::vector<std::array<std::uint32_t, 3>> triangle_texcoords;
    // Empty, or per triangle an index into materials or kNoIndex (the primitive without material).
    std::vector<std::uint32_t> triangle_materials;
    std::vector<Material> materials;
    // A skin (io/obj/skin.h): the skeleton and per position its influences, written as JOINTS_0
    // (unsigned short) and WEIGHTS_0 (floats that sum to 1), the skeleton's nodes beside the mesh's
    // and every level's node skinned by it. Levels share levels[0]'s skeleton.
    std::shared_ptr<const Skeleton> skeleton = nullptr;
    std::vector<JointInfluences> influences = {};
};

enum class GltfContainer { Json, Binary };

// Per triangle, the index in `materials` of the material its face_materials name names (the first
// with that name), or kNoIndex; empty when face_materials is.
std::vector<std::uint32_t> material_indices(const FaceLabels& face_materials, const std::vector<Material>& materials);

// What format_gltf changes so that the file is always valid glTF, one warning per kind. Of the
// materials, known from the input before any work: names that are not UTF-8 (their other bytes
// written as \xNN text), diffuse colours outside [0, 1] (clamped; not a number: 1).
std::vector<std::string> gltf_material_repairs(std::span<const Material> materials);
// Of the subdivided mesh: vertices whose normal has no direction (written as +z).
std::optional<std::string> gltf_normal_repair(const GltfMesh& mesh);

// The file content; image paths are written relative to output_folder.
std::string format_gltf(const GltfMesh& mesh, GltfContainer container, const std::string& output_folder);

// Binary for a path ending in .glb, JSON otherwise. Throws SaveError.
void save_gltf(const GltfMesh& mesh, const std::string& path);

// A set of levels of detail, finest first, in one file: each level a mesh of its own in `meshes` and
// a node of its own; the scene's one node shows LOD0 and names the others through the MSFT_lod
// extension, with MSFT_screencoverage in its extras: per level the screen coverage down to which it
// is shown (`coverage`, one per level, not increasing; the last 0, so the coarsest is never culled).
// One level alone is format_gltf's file. Materials are levels[0]'s, shared by every level.
std::string format_gltf_lods(std::span<const GltfMesh> levels, std::span<const double> coverage, GltfContainer container,
                             const std::string& output_folder);
void save_gltf_lods(std::span<const GltfMesh> levels, std::span<const double> coverage, const std::string& path);

}  // namespace rgbio
