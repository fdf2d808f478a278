#pragma once
// glTF 2.0 files (.gltf with its buffers, .glb) read through tinygltf into a ForeignMesh: the
// triangles of every mesh the default scene's nodes place (TRIANGLES, strips and fans), with the
// node transforms composed along the hierarchy (in double precision; a node without a transform
// leaves the stored floats as they are), TEXCOORD_0 (v flipped to OBJ's convention), COLOR_0,
// materials (base colour factor and an external base-colour texture), and one group per placed mesh
// when there are several, and the skin every mesh has (JOINTS_0/WEIGHTS_0 per vertex and the
// skeleton: gltf_skin.h). Normals, tangents, further UV sets, a skin not every mesh has, morph
// targets, animations, cameras, lights and embedded textures are named as dropped.
#include <string>

#include "io/formats/foreign_mesh.h"

namespace rgbio {

// Throws ObjError: Unreadable (cannot read the file), Malformed (tinygltf's error, an accessor out of
// its buffer, an index beyond the vertices, a node cycle).
ForeignMesh read_gltf_mesh(const std::string& path);

}  // namespace rgbio
