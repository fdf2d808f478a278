#pragma once
// Where a face of the adaptive mesh lies: in which base face, which triangle of the uniform
// hierarchy it is a piece of, and which face holds a given point of a base face. Everything is exact
// integer arithmetic on vertex addresses (surface_point.h).
#include <array>
#include <cstdint>

#include "rgb/mesh/handles.h"
#include "rgb/mesh/surface_point.h"

namespace rgb {

class Mesh;

// The base face whose triangle contains f (every face lies inside one).
std::uint32_t base_face_of(const Mesh& mesh, FaceId f);

// The triangle of Σl (l = level(f)) that f is a piece of (spec §1.3: f itself for a green face, the
// parent it bisects or cuts for a red or blue one), as three points of base face `base_face`.
std::array<SurfacePoint, 3> parent_triangle(const Mesh& mesh, FaceId f, std::uint32_t base_face);

// Corner numerators of a triangle in one base face: corner k is (numerators[k][0..2]) / 2^level.
using CornerNumerators = std::array<std::array<std::uint32_t, 3>, 3>;

// A face's corners in the base face holding it, over 2^top, top being its finest corner level.
struct FaceCorners {
    std::uint32_t base_face = 0;
    int top = 0;
    CornerNumerators numerators{};
};
// Throws std::logic_error when the face lies in no single base face (as base_face_of).
FaceCorners face_corners(const Mesh& mesh, FaceId f);
// The same corners over 2^level, level >= top.
CornerNumerators corners_at(const FaceCorners& corners, int level);
// The corners of the triangle of Σl (l >= top - 1) that holds the face, over 2^(l+1), in
// parent_triangle's order.
CornerNumerators parent_corners(const FaceCorners& corners, int l);

// A live face inside base face `base_face` whose closed triangle contains the point with barycentric
// numerators `target` over 2^level (level >= every vertex level in that face). Searches from a face
// at the base face's first corner towards the point.
FaceId face_containing(const Mesh& mesh, std::uint32_t base_face, const std::array<std::uint32_t, 3>& target, int level);

}  // namespace rgb
