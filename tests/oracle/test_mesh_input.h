#pragma once
// The test meshes of tests/rgb as untagged Far input.
#include "osd_far.h"
#include "support/test_meshes.h"

namespace osdoracle {

inline FarInput far_input(const rgbtest::TestMesh& m) {
    FarInput in;
    in.positions = m.positions;
    for (const auto& t : m.triangles)
        in.triangles.push_back({static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2])});
    return in;
}

}  // namespace osdoracle
