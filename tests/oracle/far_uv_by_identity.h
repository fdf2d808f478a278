#pragma once
// Far's face-varying UVs seen through the identities of the uniform Loop oracle, so that each corner
// of an adaptive RGB mesh can be compared with Far's: a UV of level k is named by the identity of its
// vertex and the base face its triangle lies in (both sides of a seam, every span of a base vertex).
// Far numbers the four children of triangle t as 4t .. 4t+3, so the base face of triangle t of
// level k is t >> 2k; the constructor checks that against Far's vertex origins.
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "far_by_identity.h"
#include "rgb/values/uv_layout.h"

namespace osdoracle {

// The core's UV channel for a Far input with UVs.
rgb::UvChannel uv_channel_of(const FarInput& input);

class FarUvByIdentity {
public:
    explicit FarUvByIdentity(const FarByIdentity& far);

    // Far's UV of level k at the vertex with identity `id`, in triangles of base face `base_face`;
    // nullptr if no triangle of that level and face has the vertex.
    const glm::dvec2* uv(int k, rgbtest::Identity id, std::uint32_t base_face) const;
    // Far's LimitFaceVarying of the finest level, named the same way.
    const glm::dvec2* limit_uv(rgbtest::Identity id, std::uint32_t base_face) const;
    double tolerance() const { return tolerance_; }  // 1e-12 of the UV bounding-box diagonal

private:
    using ByCorner = std::map<std::pair<rgbtest::Identity, std::uint32_t>, glm::dvec2>;
    // Per triangle corner values of level k (Far's triangle order) by identity and base face.
    static ByCorner by_corner(const FarLevel& level, const std::vector<rgbtest::Identity>& identities, int k,
                              const std::vector<std::array<glm::dvec2, 3>>& values);
    std::vector<ByCorner> uv_;  // [level]
    ByCorner limit_;
    double tolerance_ = 0.0;
};

}  // namespace osdoracle
