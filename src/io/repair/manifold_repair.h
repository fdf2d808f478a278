#pragma once
// Folder io/repair (validation, manifold repair, triangulation): includes io/obj and the core.
// Making a triangle soup a 2-manifold by cutting, or refusing it (strict mode).
//
// Non-manifold edges (more than two faces): at each such edge the first face in file order stays
// joined to the first later face that runs along the edge in the opposite direction (or, if none
// does, to the second face); every other face is cut off the edge. Then every vertex whose faces
// form several fans (the cut ones included, and bow-ties: fans that touch only at the vertex) gets
// one vertex per fan: the fan holding the vertex's first corner in file order keeps the vertex id,
// the others get copies in order of their first corner. Where a cut face still shares both edge
// vertices with the kept pair (its fans wrap around to them), it gets a copy of the edge's
// smaller-index vertex of its own. Every rule looks only at file order, so the same file always
// gives the same result.
#include <cstddef>
#include <string>
#include <vector>

#include "io/repair/triangle_soup.h"

namespace rgbio {

// Throws ObjError(NonManifoldEdge, NonManifoldVertex) when strict; otherwise repairs as described
// and appends a warning per kind of repair (counts and the first line). Returns the edge uses of
// the resulting triangles (computed once when nothing needed repair).
std::vector<EdgeUse> make_manifold(TriangleSoup& soup, const std::vector<std::size_t>& position_lines, const std::string& file,
                                   bool strict, std::vector<std::string>& warnings);

}  // namespace rgbio
