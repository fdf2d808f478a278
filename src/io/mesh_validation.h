#pragma once
// Second stage of loading: OBJ polygons -> a triangle mesh that rgb::Mesh accepts (an oriented
// 2-manifold, possibly with boundary). Fixable problems are fixed and reported as warnings;
// the others throw ObjError naming the OBJ line. See src/io/README.md for the table.
#include <string>

#include "io/loaded_mesh.h"
#include "io/obj_parser.h"

namespace rgbio {

// Throws ObjError (NoFaces, DegenerateFace, DuplicateFace, NonManifoldEdge, NonManifoldVertex,
// NonOrientable).
LoadedMesh validate_mesh(const ObjRecords& records, const std::string& file);

}  // namespace rgbio
