#pragma once
// Folder io/formats: meshes from files other than OBJ (glTF through tinygltf, PLY, and whatever
// Assimp reads). Each reader fills a ForeignMesh; weld_foreign_mesh turns it into the LoadedMesh the
// OBJ reader gives, through the same validation and repairs (mesh_validation.h), so every command
// and the editor take any format the way they take OBJ.
//
// A format that stores a vertex per corner (STL, glTF where a seam or a hard normal splits a
// vertex, Assimp's importers) is welded by exact position here: corners with bit-identical
// coordinates (+0 and -0 alike) become one vertex, so the surface is one manifold; what differs
// between the corners of a welded vertex (texture coordinates) stays per corner, as OBJ's vt.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "io/obj/loaded_mesh.h"
#include "io/obj/skin.h"

namespace rgbio {

struct ForeignMesh {
    std::vector<glm::dvec3> positions;   // per vertex, as the file stores them (node transforms applied)
    std::vector<glm::dvec3> colours;     // empty, or per vertex (0-1)
    std::vector<glm::dvec2> vertex_uvs;  // empty, or per vertex (OBJ's convention: v up)
    std::vector<JointInfluences> influences;  // empty, or per vertex, with `skeleton`
    std::shared_ptr<const Skeleton> skeleton;
    // Polygon i's corners are corners[face_start[i] .. face_start[i + 1]), vertex indices.
    std::vector<std::uint32_t> face_start{0};
    std::vector<std::uint32_t> corners;
    std::vector<glm::dvec2> corner_uvs;  // empty, or per corner (wins over vertex_uvs)
    std::vector<std::uint32_t> face_group;     // empty, or per face: index into group_names
    std::vector<std::uint32_t> face_material;  // empty, or per face: index into materials (or kNoIndex)
    std::vector<std::string> group_names;
    std::vector<Material> materials;
    std::vector<std::string> dropped;   // what the file has that is not kept, one phrase each
    std::vector<std::string> warnings;  // anything else worth saying

    std::size_t num_faces() const { return face_start.size() - 1; }
    void add_face(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        corners.insert(corners.end(), {a, b, c});
        face_start.push_back(static_cast<std::uint32_t>(corners.size()));
    }
};

// Welds, drops faces that welding made degenerate or duplicate (with a warning each), then
// validates and repairs as for OBJ. Throws ObjError (NoFaces, NonFiniteCoordinate,
// AbsurdCoordinate, and validate_mesh's). In messages, "line N" of such a file is its N-th face.
LoadedMesh weld_foreign_mesh(ForeignMesh&& mesh, const std::string& file, const ReadOptions& options);

// Why no reader keeps a file's normals, said after naming them: subdivision moves the positions, so
// the normals that fit the file's surface do not fit the written one, and every written normal is
// recomputed (the exact Loop limit normals: rgb/values/limit_normals.h).
inline constexpr const char* kNormalsRecomputed =
    " (not kept: written normals are recomputed as the subdivided surface's exact limit normals, where --sharp-angle keeps hard edges sharp)";

// Appends "N what" to mesh.dropped when n > 0.
void note_dropped(ForeignMesh& mesh, std::size_t n, const std::string& what);

// Keeps groups only where the file places several meshes (one is the whole surface), and the face
// materials only where some face has one.
void drop_idle_labels(ForeignMesh& mesh);

// A library's error text without the line breaks and blanks that end it.
std::string trimmed_message(std::string text);

// The material names made unique and non-empty ("material N" for an unnamed one), so that faces can
// name them as OBJ's usemtl does.
void name_materials(std::vector<Material>& materials);

}  // namespace rgbio
