#pragma once
// Every other format Assimp reads (FBX, COLLADA, 3DS, STL, OFF, Blender, ...) through Assimp into a
// ForeignMesh: the polygons of every mesh the node hierarchy places (node transforms composed in
// double precision from Assimp's single-precision matrices), the first UV set, the first colour set,
// materials (diffuse or base colour, and a diffuse or base-colour texture file), and one group per
// placed mesh when there are several. Assimp keeps positions in single precision: they are its
// floats, exactly (for STL, PLY-like binary floats that is what the file stores; for text formats
// Assimp's own number parsing decides the float).
#include <string>

#include "io/formats/foreign_mesh.h"

namespace rgbio {

// Whether Assimp has an importer for the file name's extension (".fbx", any case).
bool assimp_reads_extension(const std::string& extension);

// Throws ObjError: Unreadable (no such file), Malformed (Assimp's error message; a scene without meshes).
ForeignMesh read_assimp_mesh(const std::string& path);

}  // namespace rgbio
