#pragma once
// Second stage of loading: OBJ polygons -> a triangle mesh that rgb::Mesh accepts (an oriented
// 2-manifold, possibly with boundary), with the data that rides on its corners, faces and vertices.
// Fixable problems are fixed and reported as warnings; the others throw ObjError naming the OBJ
// line. See the table in docs/files.md.
#include <string>

#include "io/obj/loaded_mesh.h"
#include "io/obj/obj_parser.h"

namespace rgbio {

// Throws ObjError (NoFaces, DegenerateFace, DuplicateFace, NonOrientable, ComplexPolygon; and
// NonManifoldEdge, NonManifoldVertex when options.strict). May take the records' positions
// (assemble_loaded_mesh).
LoadedMesh validate_mesh(ObjRecords& records, const std::string& file, const ReadOptions& options = {});

// The faces of a file saved by rgbsub (all triangles, already clean) with their data, unchanged.
// `triangles`: those faces' corners, which the caller has at hand already (one per face). Takes the
// records' positions (assemble_loaded_mesh).
LoadedMesh saved_mesh_content(ObjRecords& records, std::vector<rgb::Triangle> triangles);

}  // namespace rgbio
