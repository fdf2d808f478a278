#pragma once
// Exact configurations of RGB triangles, written the way spec tables write them: G1(B,N,M),
// R0(A,M,C) with red edge M-C, and so on. A face matches when it has the same vertices in the same
// cyclic order (orientation included), the same colour and level, and the same red edge.
#include <array>
#include <optional>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "rgb/mesh/mesh.h"

namespace rgbtest {

struct ExpectedFace {
    std::array<rgb::VertexId, 3> v;
    rgb::Colour colour;
    int level;
    std::optional<std::pair<rgb::VertexId, rgb::VertexId>> red;  // unordered
};

ExpectedFace green(int level, rgb::VertexId a, rgb::VertexId b, rgb::VertexId c);
// A red or blue triangle (a, b, c) whose red edge joins `red_a` and `red_b`.
ExpectedFace red(int level, rgb::VertexId a, rgb::VertexId b, rgb::VertexId c, rgb::VertexId red_a, rgb::VertexId red_b);
ExpectedFace blue(int level, rgb::VertexId a, rgb::VertexId b, rgb::VertexId c, rgb::VertexId red_a, rgb::VertexId red_b);

// Every expected face is live in the mesh, as described.
testing::AssertionResult has_faces(const rgb::Mesh& mesh, const std::vector<ExpectedFace>& expected);
// has_faces, and the mesh has no other faces.
testing::AssertionResult faces_are(const rgb::Mesh& mesh, const std::vector<ExpectedFace>& expected);

struct ColourCounts {
    std::size_t green = 0, red = 0, blue = 0;
    friend bool operator==(const ColourCounts&, const ColourCounts&) = default;
};
ColourCounts colour_counts(const rgb::Mesh& mesh);
void PrintTo(const ColourCounts& c, std::ostream* os);

}  // namespace rgbtest
