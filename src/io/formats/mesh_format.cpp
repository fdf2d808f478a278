#include "io/formats/mesh_format.h"

#include "io/files/save_target.h"

namespace rgbio {

MeshFormat mesh_format(const std::string& path) {
    if (has_extension(path, ".glb") || has_extension(path, ".gltf")) return MeshFormat::Gltf;
    if (has_extension(path, ".ply")) return MeshFormat::Ply;
    if (has_extension(path, ".stl")) return MeshFormat::Stl;
    if (has_extension(path, ".vtu")) return MeshFormat::Vtu;
    if (has_extension(path, ".msh")) return MeshFormat::Msh;
    return MeshFormat::Obj;
}

std::string_view format_name(MeshFormat format) {
    switch (format) {
        case MeshFormat::Obj: return "OBJ";
        case MeshFormat::Gltf: return "glTF";
        case MeshFormat::Ply: return "PLY";
        case MeshFormat::Stl: return "STL";
        case MeshFormat::Vtu: return "VTK XML (.vtu)";
        case MeshFormat::Msh: return "Gmsh (.msh)";
    }
    return "OBJ";
}

}  // namespace rgbio
