#pragma once
// Bit-for-bit comparison of two adaptive states (doubles compared by their bytes, so -0 != +0).
#include <cstring>

#include <gtest/gtest.h>

#include "rgb/state.h"

namespace rgbio::test {

inline bool same_bits(const glm::dvec3& a, const glm::dvec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

inline void expect_identical(const rgb::MeshState& a, const rgb::MeshState& b) {
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    ASSERT_EQ(a.faces.size(), b.faces.size());
    for (std::size_t i = 0; i < a.vertices.size(); ++i) {
        const rgb::VertexState &x = a.vertices[i], &y = b.vertices[i];
        ASSERT_EQ(x.alive, y.alive) << "vertex slot " << i;
        ASSERT_EQ(x.level, y.level) << "vertex slot " << i;
        ASSERT_EQ(x.boundary, y.boundary) << "vertex slot " << i;
        ASSERT_TRUE(same_bits(x.insertion_position, y.insertion_position)) << "vertex slot " << i;
        ASSERT_EQ(x.limit.has_value(), y.limit.has_value()) << "vertex slot " << i;
        if (x.limit) {
            ASSERT_TRUE(same_bits(*x.limit, *y.limit)) << "vertex slot " << i;
        }
    }
    for (std::size_t i = 0; i < a.faces.size(); ++i) {
        ASSERT_EQ(a.faces[i].alive, b.faces[i].alive) << "face slot " << i;
        ASSERT_EQ(a.faces[i].v, b.faces[i].v) << "face slot " << i;
        ASSERT_EQ(a.faces[i].type, b.faces[i].type) << "face slot " << i;
    }
    EXPECT_EQ(a.base_valence, b.base_valence);
    EXPECT_EQ(a.free_vertices, b.free_vertices);
    EXPECT_EQ(a.free_faces, b.free_faces);
}

}  // namespace rgbio::test
