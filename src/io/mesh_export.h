#pragma once
// The adaptive mesh saved in the format its path's extension names (formats/mesh_format.h): OBJ with
// the adaptive state (mesh_file.h), glTF (gltf_export.h), or PLY, STL, VTU, MSH through the writers
// of formats/format_writers.h, which take the mesh as plain arrays (export_mesh).
#include <string>

#include "io/formats/export_mesh.h"
#include "io/formats/mesh_format.h"
#include "io/mesh_file.h"
#include "rgb/mesh/mesh.h"

namespace rgbio {

// The live vertices in slot order at the positions SaveOptions asks for, with the vertex colours (by
// the position rules, at the positions' level, as the OBJ writer writes them) and every live face with
// its level and RGB colour.
ExportMesh export_mesh(const rgb::Mesh& mesh, const SaveOptions& options);

// Whether a save to `path` is an export: a format without the adaptive state (every one but OBJ).
bool is_export_path(const std::string& path);

// Saves in the format of path's extension. Throws SaveError.
void save_mesh_file(const rgb::Mesh& mesh, const std::string& path, const SaveOptions& options);

}  // namespace rgbio
