#pragma once
// Which vertices a cage's detail (rgb/mesh/detail_positions.h) samples, by the definition in
// docs/detail.md, independently of how the core stores them: every base vertex; a point on a base
// edge up to the coarser level of the faces that hold it; a point inside a base face up to the face's
// level. The faces that hold a point are found by asking every face.
#include <algorithm>
#include <cstdint>
#include <span>

#include "rgb/mesh/base_mesh.h"
#include "rgb/mesh/detail_positions.h"
#include "rgb/mesh/surface_point.h"

namespace rgbtest {

inline bool sampled_by_definition(const rgb::BaseMesh& base, std::span<const std::uint8_t> face_levels, const rgb::SurfacePoint& p) {
    const rgb::SurfacePoint r = rgb::reduced(p);
    int coarsest = rgb::DetailPositions::kMaxLevel;
    for (std::uint32_t g = 0; g < base.num_faces(); ++g)
        if (rgb::in_face(base, r, g)) coarsest = std::min(coarsest, int(face_levels[g]));
    return r.level <= coarsest;
}

}  // namespace rgbtest
