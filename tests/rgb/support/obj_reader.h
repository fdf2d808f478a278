#pragma once
// A minimal OBJ reader for test assets: `v x y z` and triangular `f a b c` lines (indices may carry
// /texture/normal parts, which are ignored); everything else is skipped. The tests must not depend
// on src/io, whose reader is itself under test elsewhere.
#include <string>

#include "support/test_meshes.h"

namespace rgbtest {

// Throws std::runtime_error naming the file, line and problem.
TestMesh read_obj(const std::string& path);

}  // namespace rgbtest
