#pragma once
// PLY files (ASCII, binary little and big endian) read by rgbsub itself into a ForeignMesh, so that
// positions come back exactly as stored: `double` properties as doubles, `float` ones as floats,
// ASCII numbers correctly rounded to double (std::from_chars), as OBJ's. Read: the vertex
// element's x, y, z, its colour (red, green, blue: integer types scaled to 0-1) and texture
// coordinates (s/t, u/v or texture_u/texture_v); the face element's vertex_indices (or
// vertex_index) and per-corner texcoord lists. Other properties and elements (normals, alpha,
// edges, ...) are named as dropped.
#include <string>

#include "io/formats/foreign_mesh.h"

namespace rgbio {

// Throws ObjError: Unreadable, Malformed (a bad header, a file that ends early, a number that does
// not parse, a list longer than the file).
ForeignMesh read_ply_mesh(const std::string& path);

}  // namespace rgbio
