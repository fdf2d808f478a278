#pragma once
// Folder io/formats (mesh files other than OBJ and glTF): includes io/obj, io/files and the core.
// Which format an output path asks for: its extension, without regard to ASCII case (save_target.h
// has_extension). The one place `-o`, `rgbsub lods` and the editor's Save as decide it.
#include <string>
#include <string_view>

namespace rgbio {

enum class MeshFormat {
    Obj,   // .obj and any extension not below: OBJ with the adaptive state
    Gltf,  // .glb (binary container) or .gltf (JSON)
    Ply,   // binary little-endian PLY
    Stl,   // binary STL
    Vtu,   // VTK XML UnstructuredGrid
    Msh,   // Gmsh 4.1
};

MeshFormat mesh_format(const std::string& path);

// "OBJ", "glTF", "PLY", "STL", "VTK XML (.vtu)", "Gmsh (.msh)", for messages.
std::string_view format_name(MeshFormat format);

}  // namespace rgbio
