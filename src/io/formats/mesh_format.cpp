#include "io/formats/mesh_format.h"

#include <algorithm>
#include <filesystem>

#include "io/formats/assimp_reader.h"
#include "io/formats/gltf_reader.h"
#include "io/formats/ply_reader.h"
#include "io/files/save_target.h"

namespace rgbio {

namespace {

std::string lower_extension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

}  // namespace

MeshFormat mesh_format(const std::string& path) {
    const std::string extension = lower_extension(path);
    if (extension == ".obj") return MeshFormat::Obj;
    if (extension == ".gltf" || extension == ".glb") return MeshFormat::Gltf;
    if (extension == ".ply") return MeshFormat::Ply;
    return assimp_reads_extension(extension) ? MeshFormat::Assimp : MeshFormat::Obj;
}

bool has_mesh_extension(const std::string& path) { return lower_extension(path) == ".obj" || mesh_format(path) != MeshFormat::Obj; }

LoadedMesh read_foreign_file(const std::string& path, MeshFormat format, const ReadOptions& options) {
    ForeignMesh mesh = format == MeshFormat::Gltf  ? read_gltf_mesh(path)
                       : format == MeshFormat::Ply ? read_ply_mesh(path)
                                                   : read_assimp_mesh(path);
    LoadedMesh loaded = weld_foreign_mesh(std::move(mesh), path, options);
    options.progress.done();
    return loaded;
}

OutputFormat output_format(const std::string& path) {
    if (has_extension(path, ".glb") || has_extension(path, ".gltf")) return OutputFormat::Gltf;
    if (has_extension(path, ".ply")) return OutputFormat::Ply;
    if (has_extension(path, ".stl")) return OutputFormat::Stl;
    if (has_extension(path, ".vtu")) return OutputFormat::Vtu;
    if (has_extension(path, ".msh")) return OutputFormat::Msh;
    return OutputFormat::Obj;
}

std::string_view format_name(OutputFormat format) {
    switch (format) {
        case OutputFormat::Obj: return "OBJ";
        case OutputFormat::Gltf: return "glTF";
        case OutputFormat::Ply: return "PLY";
        case OutputFormat::Stl: return "STL";
        case OutputFormat::Vtu: return "VTK XML (.vtu)";
        case OutputFormat::Msh: return "Gmsh (.msh)";
    }
    return "OBJ";
}

}  // namespace rgbio
