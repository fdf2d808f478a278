#pragma once
// The adaptive mesh as a glTF 2.0 file (gltf_writer.h), for pipelines: its positions (displayed or
// limit, as SaveOptions says), the exact limit normals (rgb/values/limit_normals.h), one primitive per
// material of the base faces the triangles lie in, the materials the .mtl libraries define (base
// colour, or base colour texture), every corner's exact texture coordinate from SaveOptions::uvs (the
// OBJ writer's vt; without a UV layout, the level-0 ones while the mesh is its base mesh, and
// dropped_attributes says what a refined one leaves out), and the vertex colours by the position
// rules (rgb/values/vertex_channel.h) as COLOR_0, and a skin's joint weights by the same rules
// (skin_weights.h) as JOINTS_0/WEIGHTS_0, all at the positions' level.
#include <string>

#include "io/gltf/gltf_writer.h"
#include "io/mesh_file.h"
#include "rgb/mesh/mesh.h"

namespace rgbio {

// Whether `path` names a glTF file (.glb or .gltf, any case: formats/mesh_format.h).
bool is_gltf_path(const std::string& path);

GltfMesh gltf_mesh(const rgb::Mesh& mesh, const SaveOptions& options);

// save_gltf(gltf_mesh(mesh, options), path). Throws SaveError.
void export_gltf(const rgb::Mesh& mesh, const std::string& path, const SaveOptions& options);

}  // namespace rgbio
