#include "io/formats/assimp_reader.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "io/files/file_text.h"
#include "io/obj/obj_error.h"

namespace rgbio {

namespace {

namespace fs = std::filesystem;

glm::dmat4 to_dmat4(const aiMatrix4x4& m) {
    glm::dmat4 out;  // Assimp's matrices are row-major, glm's column-major
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) out[c][r] = m[static_cast<unsigned>(r)][static_cast<unsigned>(c)];
    return out;
}

struct Walk {
    const aiScene& scene;
    const std::string& path;
    ForeignMesh& out;
    std::size_t normals = 0, extra_uvs = 0, skinned = 0, morphed = 0, lines_or_points = 0;
};

void add_mesh(Walk& w, const aiMesh& mesh, const glm::dmat4& transform, std::uint32_t group) {
    ForeignMesh& out = w.out;
    const std::size_t first = out.positions.size();
    const bool identity = transform == glm::dmat4(1.0);
    for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
        const glm::dvec3 x(mesh.mVertices[i].x, mesh.mVertices[i].y, mesh.mVertices[i].z);
        out.positions.push_back(identity ? x : glm::dvec3(transform * glm::dvec4(x, 1.0)));
    }
    w.normals += mesh.mNormals != nullptr;
    w.extra_uvs += mesh.mTextureCoords[1] != nullptr;
    w.skinned += mesh.mNumBones > 0;
    w.morphed += mesh.mNumAnimMeshes > 0;
    if (mesh.mTextureCoords[0] || !out.vertex_uvs.empty()) {
        out.vertex_uvs.resize(first, glm::dvec2(0.0));
        for (unsigned i = 0; i < mesh.mNumVertices; ++i)
            out.vertex_uvs.push_back(mesh.mTextureCoords[0] ? glm::dvec2(mesh.mTextureCoords[0][i].x, mesh.mTextureCoords[0][i].y) : glm::dvec2(0.0));
    }
    if (mesh.mColors[0] || !out.colours.empty()) {
        out.colours.resize(first, glm::dvec3(1.0));
        for (unsigned i = 0; i < mesh.mNumVertices; ++i)
            out.colours.push_back(mesh.mColors[0] ? glm::dvec3(mesh.mColors[0][i].r, mesh.mColors[0][i].g, mesh.mColors[0][i].b) : glm::dvec3(1.0));
    }
    const bool mirrored = glm::determinant(glm::dmat3(transform)) < 0.0;
    const std::uint32_t material = mesh.mMaterialIndex < out.materials.size() ? mesh.mMaterialIndex : kNoIndex;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace& face = mesh.mFaces[f];
        if (face.mNumIndices < 3) {
            ++w.lines_or_points;
            continue;
        }
        for (unsigned k = 0; k < face.mNumIndices; ++k) {
            const unsigned i = face.mIndices[mirrored ? face.mNumIndices - 1 - k : k];
            if (i >= mesh.mNumVertices)
                throw ObjError(ObjProblem::Malformed, w.path, 0, "a face of mesh '" + std::string(mesh.mName.C_Str()) + "' names vertex " +
                                                                     std::to_string(i) + " of " + std::to_string(mesh.mNumVertices));
            out.corners.push_back(static_cast<std::uint32_t>(first + i));
        }
        out.face_start.push_back(static_cast<std::uint32_t>(out.corners.size()));
        out.face_material.push_back(material);
        out.face_group.push_back(group);
    }
}

void add_node(Walk& w, const aiNode& node, const glm::dmat4& parent, unsigned depth) {
    // Assimp's importers build trees; a guard all the same against a corrupt one looping.
    if (depth > 1000) throw ObjError(ObjProblem::Malformed, w.path, 0, "the node hierarchy is more than 1000 levels deep");
    const glm::dmat4 transform = parent * to_dmat4(node.mTransformation);
    for (unsigned k = 0; k < node.mNumMeshes; ++k) {
        const unsigned m = node.mMeshes[k];
        if (m >= w.scene.mNumMeshes) throw ObjError(ObjProblem::Malformed, w.path, 0, "a node names a mesh that does not exist");
        const aiMesh& mesh = *w.scene.mMeshes[m];
        const std::uint32_t group = static_cast<std::uint32_t>(w.out.group_names.size());
        const std::string name = mesh.mName.length > 0 ? mesh.mName.C_Str() : node.mName.C_Str();
        w.out.group_names.push_back(name.empty() ? "mesh " + std::to_string(m + 1) : name);
        add_mesh(w, mesh, transform, group);
    }
    for (unsigned c = 0; c < node.mNumChildren; ++c) add_node(w, *node.mChildren[c], transform, depth + 1);
}

void read_materials(const aiScene& scene, const fs::path& folder, ForeignMesh& out) {
    std::size_t embedded = 0;
    for (unsigned i = 0; i < scene.mNumMaterials; ++i) {
        const aiMaterial& m = *scene.mMaterials[i];
        Material material;
        aiString name;
        if (m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) material.name = name.C_Str();
        aiColor4D colour(0.6f, 0.6f, 0.6f, 1.0f);
        if (m.Get(AI_MATKEY_BASE_COLOR, colour) != AI_SUCCESS) m.Get(AI_MATKEY_COLOR_DIFFUSE, colour);
        material.diffuse = glm::dvec3(colour.r, colour.g, colour.b);
        aiString texture;
        if (m.GetTexture(aiTextureType_DIFFUSE, 0, &texture) == AI_SUCCESS || m.GetTexture(aiTextureType_BASE_COLOR, 0, &texture) == AI_SUCCESS) {
            std::string file = texture.C_Str();
            std::replace(file.begin(), file.end(), '\\', '/');
            if (file.starts_with('*') || scene.GetEmbeddedTexture(texture.C_Str()) != nullptr) ++embedded;
            else if (!file.empty()) material.diffuse_texture = (folder / file).lexically_normal().string();
        }
        out.materials.push_back(std::move(material));
    }
    name_materials(out.materials);
    if (embedded > 0) out.dropped.push_back(std::to_string(embedded) + " textures embedded in the file (only image files beside it are kept)");
}

// Assimp's OFF importer believes the counts of the header and spends minutes on a file that claims
// billions of vertices (the corpus's invalid/OutOfMemory.off): counts the file's size cannot hold
// are refused first. Each vertex takes 6 bytes at least ("0 0 0\n"), each face 8 ("3 0 1 2\n").
void check_off_counts(std::string_view text, const std::string& path) {
    std::istringstream in{std::string(text.substr(0, 256))};
    std::string keyword;
    double vertices = 0, faces = 0;
    if (!(in >> keyword) || !keyword.ends_with("OFF") || !(in >> vertices >> faces)) return;
    if (vertices > static_cast<double>(text.size()) / 6 || faces > static_cast<double>(text.size()) / 8)
        throw ObjError(ObjProblem::Malformed, path, 0,
                       "its header counts " + std::to_string(static_cast<long long>(vertices)) + " vertices and " +
                           std::to_string(static_cast<long long>(faces)) + " faces, more than its " + std::to_string(text.size()) + " bytes can hold");
}

}  // namespace

bool assimp_reads_extension(const std::string& extension) {
    // One importer's registry, kept: building it costs about a millisecond.
    static const Assimp::Importer importer;
    return !extension.empty() && importer.IsExtensionSupported(extension);
}

ForeignMesh read_assimp_mesh(const std::string& path) {
    // Opened first for the same "cannot read" message every reader gives (Assimp's would be vaguer).
    const FileText text = read_file_text(path);
    check_off_counts(text.view(), path);
    Assimp::Importer importer;
    // Points and lines stay apart from faces; Assimp's checks of its own structures keep a broken
    // importer's output from reaching the walk below.
    // Polygons are triangulated by Assimp, so that faces welding makes duplicates of each other are
    // found and dropped as triangles (foreign_mesh.h).
    const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure | aiProcess_Triangulate);
    if (!scene) {
        const std::string error = trimmed_message(importer.GetErrorString());
        throw ObjError(ObjProblem::Malformed, path, 0, "Assimp cannot read it: " + (error.empty() ? std::string("no reason given") : error));
    }
    if (!scene->mRootNode || scene->mNumMeshes == 0)
        throw ObjError(ObjProblem::NoFaces, path, 0, "no faces: Assimp reads no mesh from it, but rgbsub needs a triangle surface");
    ForeignMesh out;
    read_materials(*scene, fs::path(path).parent_path(), out);
    Walk w{*scene, path, out};
    add_node(w, *scene->mRootNode, glm::dmat4(1.0), 0);
    note_dropped(out, w.normals, std::string("meshes' normals") + kNormalsRecomputed);
    note_dropped(out, w.extra_uvs, "meshes' second texture coordinate sets");
    note_dropped(out, w.skinned, "skinned meshes' bones and weights");
    note_dropped(out, w.morphed, "meshes' morph targets");
    note_dropped(out, scene->mNumAnimations, "animations");
    note_dropped(out, scene->mNumCameras, "cameras");
    note_dropped(out, scene->mNumLights, "lights");
    note_dropped(out, w.lines_or_points, "points and lines");
    drop_idle_labels(out);
    return out;
}

}  // namespace rgbio
