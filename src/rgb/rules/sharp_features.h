#pragma once
// Crease and corner tags of a base mesh (issue 13), on OpenSubdiv's sharpness scale, and the boundary
// option; docs/loop-creases.md §1-2 states the rules they select. They belong to the base mesh
// (base_mesh.h): every adaptive mesh refined from it shares them.
//
// Sharpness is an integer: 0 smooth, 1-9 semi-sharp (sharp rules for that many levels, then smooth),
// 10 infinitely sharp (Sdc::Crease::SHARPNESS_INFINITE). Boundary edges are infinitely sharp
// whatever the tags say.
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace rgb {

inline constexpr int kInfiniteSharpness = 10;

// Whether a feature of this (base) sharpness is still sharp at level k: semi-sharp ones lose one
// unit per level (uniform creasing), infinite ones never do.
inline bool sharp_at_level(int sharpness, int level) { return sharpness >= kInfiniteSharpness || sharpness > level; }

// Sdc::Options::VtxBoundaryInterpolation: edge-only keeps the spec's boundary rule; edge-and-corner
// also makes every boundary vertex with a single face a corner.
enum class BoundaryInterpolation : std::uint8_t { EdgeOnly, EdgeAndCorner };

const char* boundary_interpolation_name(BoundaryInterpolation b);  // "edge-only", "edge-and-corner"
std::optional<BoundaryInterpolation> parse_boundary_interpolation(std::string_view name);

struct EdgeSharpness {
    std::uint32_t a = 0, b = 0;  // base vertices; the edge must exist
    int sharpness = kInfiniteSharpness;
    friend bool operator==(const EdgeSharpness&, const EdgeSharpness&) = default;
};

struct VertexSharpness {
    std::uint32_t vertex = 0;
    int sharpness = kInfiniteSharpness;
    friend bool operator==(const VertexSharpness&, const VertexSharpness&) = default;
};

struct SharpFeatures {
    std::vector<EdgeSharpness> edges;
    std::vector<VertexSharpness> corners;
    BoundaryInterpolation boundary = BoundaryInterpolation::EdgeOnly;
    friend bool operator==(const SharpFeatures&, const SharpFeatures&) = default;
};

}  // namespace rgb
