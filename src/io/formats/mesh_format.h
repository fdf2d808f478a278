#pragma once
// Which reader a mesh file goes to, by its extension in any case: .obj to rgbsub's OBJ reader
// (obj_reader.h, in src/io), .gltf/.glb to tinygltf, .ply to rgbsub's PLY reader, any other
// extension Assimp has an importer for to Assimp; a name with none of these is read as OBJ, as
// before other formats were read.
#include <string>
#include <string_view>

#include "io/obj/loaded_mesh.h"

namespace rgbio {

enum class MeshFormat { Obj, Gltf, Ply, Assimp };

MeshFormat mesh_format(const std::string& path);

// Whether the name has the extension of a format rgbsub reads (OBJ included): what the editor's file
// browser lists and what a first word must end with to open the editor.
bool has_mesh_extension(const std::string& path);

// Reads a file of a format other than OBJ into the LoadedMesh the OBJ reader would give for the same
// surface (weld_foreign_mesh). Throws ObjError.
LoadedMesh read_foreign_file(const std::string& path, MeshFormat format, const ReadOptions& options = {});

// Which format an output path asks for: its extension, without regard to ASCII case (save_target.h
// has_extension). The one place `-o`, `rgbsub lods` and the editor's Save as decide it.
enum class OutputFormat {
    Obj,   // .obj and any extension not below: OBJ with the adaptive state
    Gltf,  // .glb (binary container) or .gltf (JSON)
    Ply,   // binary little-endian PLY
    Stl,   // binary STL
    Vtu,   // VTK XML UnstructuredGrid
    Msh,   // Gmsh 4.1
};

OutputFormat output_format(const std::string& path);

// How a .msh output is written: Gmsh 4.1 ASCII (file-type 0, what Gmsh itself writes unless asked
// for binary) or binary (file-type 1: about half the size, and read without parsing decimals).
enum class MshEncoding { Ascii, Binary };

// "OBJ", "glTF", "PLY", "STL", "VTK XML (.vtu)", "Gmsh (.msh)", for messages.
std::string_view format_name(OutputFormat format);

}  // namespace rgbio
