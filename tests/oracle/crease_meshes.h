#pragma once
// Tagged meshes for the crease closed-form tests (issue 13's list): a crease loop, crease chains ending
// in corners or darts, creases meeting the boundary under both boundary options, darts of valences 3
// to 8, an irregular interior crease vertex, and semi-sharp sharpness 1-3 on edges and corners. The
// positions are the jittered test meshes of tests/rgb, so no symmetry hides a wrong weight.
#include <ostream>
#include <string>
#include <vector>

#include "osd_far.h"

namespace osdoracle {

struct CreaseCase {
    std::string name;
    FarInput input;
};

inline void PrintTo(const CreaseCase& c, std::ostream* os) { *os << c.name; }

std::vector<CreaseCase> crease_cases();

}  // namespace osdoracle
