#pragma once
// What a triangle is in an RGB triangulation: colour, level and (for red and blue triangles) which of
// its three edges is the red one. Edge colours and levels are derived from this and the vertex levels
// (spec §1.4), so edges need no storage.
#include <cstdint>

namespace rgb {

enum class Colour : std::uint8_t { Green = 0, Red = 1, Blue = 2 };

struct FaceType {
    Colour colour = Colour::Green;
    std::uint8_t level = 0;
    // Index i of the red edge (corner i to corner i+1); meaningless for green triangles.
    std::uint8_t red_edge = 0;

    friend bool operator==(const FaceType&, const FaceType&) = default;
};

// Colour and level of an edge, as seen from one incident triangle.
struct EdgeType {
    Colour colour = Colour::Green;  // Green or Red only
    int level = 0;
    friend bool operator==(const EdgeType&, const EdgeType&) = default;
};

const char* colour_name(Colour c);

}  // namespace rgb
