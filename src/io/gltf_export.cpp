#include "io/gltf_export.h"

#include "io/formats/mesh_format.h"
#include "io/mesh_export.h"
#include "io/skin_weights.h"
#include "rgb/mesh/face_location.h"
#include "rgb/values/limit_normals.h"
#include "rgb/values/mesh_uvs.h"
#include "rgb/values/uv_evaluator.h"

namespace rgbio {

bool is_gltf_path(const std::string& path) { return output_format(path) == OutputFormat::Gltf; }

GltfMesh gltf_mesh(const rgb::Mesh& mesh, const SaveOptions& options) {
    GltfMesh out;
    const bool limit = options.positions == SavedPositions::Limit;
    const BaseAttributes* attributes = options.attributes.get();
    // Positions, colours and triangles as every other format writes them, live vertices in slot order.
    ExportMesh flat = export_mesh(mesh, options);
    out.positions = std::move(flat.positions);
    out.colours = std::move(flat.colours);
    out.triangles = std::move(flat.triangles);
    const std::vector<glm::dvec3> normals = rgb::limit_normals(mesh);
    out.normals.reserve(out.positions.size());
    for (rgb::VertexId v : mesh.vertices()) out.normals.push_back(normals[v.idx]);
    // The exact UV channel gives every corner's UV at every level (the OBJ writer's vt); without it,
    // the level-0 texture coordinates serve while the mesh is its base mesh.
    rgb::MeshUvs uvs;
    if (options.uvs) {
        rgb::UvEvaluator evaluator(mesh.base(), *options.uvs);
        uvs = rgb::mesh_uvs(mesh, evaluator, limit);
        out.texcoords = uvs.values;
    }
    static_assert(rgb::MeshUvs::kNone == kNoIndex, "a corner without a UV is kNoIndex in both");
    const bool texcoords = !options.uvs && attributes && is_base_mesh(mesh) && !attributes->triangle_texcoords.empty();
    FaceLabels materials;  // per written triangle, for material_indices
    if (attributes && !attributes->labels.materials.empty()) materials.names = attributes->labels.materials.names;
    for (rgb::FaceId f : mesh.faces()) {
        if (options.uvs) out.triangle_texcoords.push_back(uvs.corners[f.idx]);
        if (texcoords)
            out.triangle_texcoords.push_back({base_corner_texcoord(mesh, *attributes, f, 0), base_corner_texcoord(mesh, *attributes, f, 1),
                                              base_corner_texcoord(mesh, *attributes, f, 2)});
        if (!materials.names.empty()) materials.of_triangle.push_back(attributes->labels.materials.of_triangle[rgb::base_face_of(mesh, f)]);
    }
    if (texcoords) out.texcoords = attributes->texcoords;
    if (attributes && attributes->skeleton) {
        const std::vector<JointInfluences> influences =
            vertex_influences(mesh, attributes->influences, limit ? rgb::ChannelLevel::Limit : rgb::ChannelLevel::Displayed);
        out.skeleton = attributes->skeleton;
        out.influences.reserve(out.positions.size());
        for (rgb::VertexId v : mesh.vertices()) out.influences.push_back(influences[v.idx]);
    }
    if (attributes) {
        out.materials = attributes->materials;
        out.triangle_materials = material_indices(materials, out.materials);
    }
    return out;
}

void export_gltf(const rgb::Mesh& mesh, const std::string& path, const SaveOptions& options) {
    save_gltf(gltf_mesh(mesh, options), path);
}

}  // namespace rgbio
