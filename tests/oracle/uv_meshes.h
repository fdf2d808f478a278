#pragma once
// Meshes with a UV channel for the face-varying tests (issue 12's list): seams across a grid and
// ending inside it (a UV dart), three and four seams meeting, a one-triangle UV island, a closed mesh
// cut along its equator with and without a geometric crease there, seams crossing infinitely sharp
// and semi-sharp edges, a semi-sharp corner on a seam, and both boundary options. The UV
// interpolation option is left to the test.
#include <ostream>
#include <string>
#include <vector>

#include "osd_far.h"

namespace osdoracle {

struct UvCase {
    std::string name;
    FarInput input;  // input.uv is set
};

inline void PrintTo(const UvCase& c, std::ostream* os) { *os << c.name; }

std::vector<UvCase> uv_cases();

// UV bow-ties: a UV value used by two separate groups of triangles around a vertex, where Far's
// sibling assignment decides which groups share a value (docs/loop-face-varying.md §5). The closed
// form tests' model of the UV topology (uv_topology.h) does not follow that assignment, so these are
// checked only against Far's refinement (uv_refinement_test.cpp).
std::vector<UvCase> uv_bow_tie_cases();

}  // namespace osdoracle
