#pragma once
// The last stage of loading: a manifold, oriented triangle soup becomes the LoadedMesh, with the
// vertices the faces use and the data that rides on them.
#include <string>
#include <vector>

#include "io/obj/loaded_mesh.h"
#include "io/obj/obj_parser.h"
#include "io/repair/triangle_soup.h"

namespace rgbio {

// Vertices: those used by a face, the file's first in file order, then the copies repairs made
// (renumbered; removing unused ones is reported). Colours only if every used vertex has one
// (otherwise dropped, reported). Texture coordinates: the used vt entries in file order. Labels and
// smoothing groups per triangle from its OBJ face. mesh.warnings: what the parser skipped or
// dropped, then `fixes`, then the removals above. When the vertices are the file's as they are (every
// one used, none renumbered: always so for a saved file), the records' positions are moved into the
// result rather than copied (tens of megabytes for a large file); the rest of the records stays.
LoadedMesh assemble_loaded_mesh(ObjRecords& records, TriangleSoup&& soup, std::vector<std::string>&& fixes);

}  // namespace rgbio
