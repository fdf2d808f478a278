#pragma once
// Bit-for-bit comparison of two adaptive states in a test (mesh_state_difference.h says where).
#include <gtest/gtest.h>

#include "mesh_state_difference.h"

namespace rgbio::test {

inline void expect_identical(const rgb::MeshState& a, const rgb::MeshState& b) { EXPECT_EQ(state_difference(a, b), ""); }

}  // namespace rgbio::test
