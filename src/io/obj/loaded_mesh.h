#pragma once
// The result of reading an OBJ file: a clean, consistently oriented manifold triangle mesh without
// unreferenced vertices, the data that rides on it (texture coordinates, vertex colours, materials,
// groups, objects, smoothing groups), plus what was fixed along the way, and the adaptive mesh when
// the file holds an rgbsub state that reproduces it exactly.
//
// Every per-triangle and per-corner array below is either empty (the file has no such data) or has
// exactly one entry per triangle, in the order of `triangles`; corner k of an entry belongs to
// corner k of the triangle, also after the loader flipped a triangle to orient it.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "io/obj/skin.h"
#include "rgb/mesh/mesh.h"
#include "rgb/support/progress.h"
#include "rgb/values/uv_layout.h"

namespace rgbio {

// How to read a file: how strictly, and who watches.
struct ReadOptions {
    // Refuse non-manifold edges and vertices (ObjError) instead of cutting them apart.
    bool strict = false;
    // Told how far the reading is: bytes read and parsed, then the saved state restored (faces
    // typed, positions computed, checked).
    rgb::ProgressSpan progress = {};
};

// "No entry": a corner without a texture coordinate, a face before any usemtl/g/o line.
inline constexpr std::uint32_t kNoIndex = UINT32_MAX;

// Face labels from usemtl, g or o lines: each triangle carries the label of its OBJ face.
struct FaceLabels {
    std::vector<std::string> names;         // as written (trimmed), in order of first use by a face
    std::vector<std::uint32_t> of_triangle;  // empty, or per triangle: index into names, or kNoIndex
    bool empty() const { return of_triangle.empty(); }
    friend bool operator==(const FaceLabels&, const FaceLabels&) = default;
};

// The labels of the base mesh's faces (of_triangle indexed by base face): every face of an adaptive
// mesh lies in one base face (rgb::base_face_of) and inherits that face's labels.
struct BaseFaceLabels {
    FaceLabels materials, groups, objects;
    std::vector<std::uint32_t> smoothing_groups;  // empty, or per base face (0 = off)
    bool empty() const { return materials.empty() && groups.empty() && objects.empty() && smoothing_groups.empty(); }
    friend bool operator==(const BaseFaceLabels&, const BaseFaceLabels&) = default;
};

// One material of a `.mtl` library named by `mtllib` (read with tinyobjloader).
struct Material {
    std::string name{};                  // newmtl, trimmed
    glm::dvec3 diffuse{0.0};             // Kd as tinyobjloader reads it (not always correctly rounded;
                                         // its default where absent: 0, or 0.6 with map_Kd)
    std::string diffuse_texture{};       // map_Kd as a path: relative ones resolved against the .mtl's
                                         // folder, '\' read as '/'; empty without map_Kd
    std::string library{};               // the .mtl file it came from (resolved path)
};

struct LoadedMesh {
    std::vector<glm::dvec3> positions;
    std::vector<rgb::Triangle> triangles;
    std::vector<std::string> warnings;  // fixes and ignored content, one readable sentence each
    // Crease and corner tags from OpenSubdiv tag lines (crease_tags.h), in this mesh's numbering.
    rgb::SharpFeatures sharp_features;
    // Per vertex: the 0-based index of the file's v line it comes from (repairs can copy one).
    std::vector<std::uint32_t> file_vertex;
    // Present when the file was saved by rgbsub with its adaptive state and the state gives back the
    // file's v and f lines exactly: the adaptive mesh. positions/triangles then are the file's plain
    // OBJ content (what other programs see).
    std::shared_ptr<rgb::Mesh> adaptive;
    // With `adaptive`: the labels of its base faces, from the state (face_label_state.h). The
    // face_* fields below are those of the file's faces, as for any file.
    BaseFaceLabels adaptive_labels;

    // Vertex colours (`v x y z r g b`), values as written: empty, or one per position. Kept only
    // when every vertex used by a face has one; otherwise all are dropped with a warning.
    std::vector<glm::dvec3> colours;
    // With `adaptive`: the base vertices' colours from the state's base-colours section (one per base
    // vertex), if it has one and the v lines carry the colours it gives.
    std::vector<glm::dvec3> base_colours;

    // Texture coordinates, face-varying: the `vt` table (u, v; used entries only, in file order)
    // and, per triangle, the table index of each corner or kNoIndex (a corner written without vt).
    // triangle_texcoords is empty when no face corner names a vt.
    std::vector<glm::dvec2> texcoords;
    std::vector<std::array<std::uint32_t, 3>> triangle_texcoords;
    // With `adaptive`: the base mesh's UV channel from the state's base-uvs section, if it has one
    // (texcoords above are then the saved mesh's, corner by corner of its f lines).
    std::optional<rgb::UvChannel> base_uvs;

    // A glTF skin (skin.h): the skeleton, and per position its joints' weights; null and empty
    // without (OBJ never has one).
    std::shared_ptr<const Skeleton> skeleton;
    std::vector<JointInfluences> influences;

    FaceLabels face_materials;  // usemtl; a name refers to the entry of `materials` with that name
    FaceLabels face_groups;     // g (all names of one g line, as written, form one label)
    FaceLabels face_objects;    // o
    std::vector<std::uint32_t> face_smoothing_groups;  // s: empty, or per triangle (0 = off)

    std::vector<std::string> material_libraries;  // mtllib file names as written, in order
    std::vector<Material> materials;              // what read_obj_file found in them, in order
};

}  // namespace rgbio
