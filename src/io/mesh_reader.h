#pragma once
// Any mesh file into a LoadedMesh, by its extension (formats/mesh_format.h): OBJ through rgbsub's
// reader (obj_reader.h), with its saved state and material libraries; glTF, PLY and Assimp's formats
// through io/formats. The one place the CLI and the editor read a mesh file through.
#include <string>

#include "io/obj/loaded_mesh.h"

namespace rgbio {

// Throws ObjError (Unreadable where the file cannot be read; a problem of its content otherwise).
LoadedMesh read_mesh_file(const std::string& path, const ReadOptions& options = {});

}  // namespace rgbio
