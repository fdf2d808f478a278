#include "far_uv_by_identity.h"

#include <algorithm>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace osdoracle {

rgb::UvChannel uv_channel_of(const FarInput& input) {
    rgb::UvChannel c;
    c.values = input.uv->values;
    for (const auto& t : input.uv->corners)
        c.corners.push_back({static_cast<std::uint32_t>(t[0]), static_cast<std::uint32_t>(t[1]), static_cast<std::uint32_t>(t[2])});
    switch (input.uv->interpolation) {
    case UvInterpolation::none: c.interpolation = rgb::UvInterpolation::None; break;
    case UvInterpolation::corners_only: c.interpolation = rgb::UvInterpolation::Corners; break;
    case UvInterpolation::boundaries: c.interpolation = rgb::UvInterpolation::Boundaries; break;
    case UvInterpolation::all: c.interpolation = rgb::UvInterpolation::All; break;
    default: throw std::invalid_argument("uv_channel_of: the core has no CORNERS_PLUS options");
    }
    return c;
}

FarUvByIdentity::FarUvByIdentity(const FarByIdentity& far) {
    const FarRefinement& r = far.refinement();
    const std::vector<std::vector<rgbtest::Identity>> identities = identities_of(r, far.oracle());
    glm::dvec2 lo(1e300), hi(-1e300);
    for (const auto& t : r.levels[0].uv)
        for (const glm::dvec2& p : t) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    tolerance_ = 1e-12 * glm::distance(lo, hi);
    for (std::size_t k = 0; k < r.levels.size(); ++k) {
        const FarLevel& level = r.levels[k];
        if (k > 0) {
            // Every vertex of triangle t comes from a vertex or an edge of triangle t / 4 one level up.
            const FarLevel& coarse = r.levels[k - 1];
            for (std::size_t t = 0; t < level.triangles.size(); ++t) {
                const auto& parent = coarse.triangles[t / 4];
                auto in_parent = [&](int v) { return std::find(parent.begin(), parent.end(), v) != parent.end(); };
                for (int v : level.triangles[t]) {
                    const VertexOrigin& o = level.origins[static_cast<std::size_t>(v)];
                    if (!in_parent(o.a) || (o.on_edge && !in_parent(o.b)))
                        throw std::logic_error("Far's triangle " + std::to_string(t) + " of level " + std::to_string(k) +
                                               " is not a child of triangle t / 4");
                }
            }
        }
        uv_.push_back(by_corner(level, identities[k], static_cast<int>(k), level.uv));
    }
    const int last = static_cast<int>(r.levels.size()) - 1;
    limit_ = by_corner(r.levels.back(), identities.back(), last, r.limit_uv);
}

FarUvByIdentity::ByCorner FarUvByIdentity::by_corner(const FarLevel& level, const std::vector<rgbtest::Identity>& identities,
                                                     int k, const std::vector<std::array<glm::dvec2, 3>>& values) {
    ByCorner by_key;
    for (std::size_t t = 0; t < level.triangles.size(); ++t) {
        const auto base_face = static_cast<std::uint32_t>(t >> (2 * k));
        for (int c = 0; c < 3; ++c) {
            const rgbtest::Identity id = identities[static_cast<std::size_t>(level.triangles[t][c])];
            const auto [it, added] = by_key.emplace(std::pair{id, base_face}, values[t][c]);
            if (!added && it->second != values[t][c]) throw std::logic_error("Far has two UVs for one vertex inside one base face");
        }
    }
    return by_key;
}

const glm::dvec2* FarUvByIdentity::limit_uv(rgbtest::Identity id, std::uint32_t base_face) const {
    const auto it = limit_.find({id, base_face});
    return it == limit_.end() ? nullptr : &it->second;
}

const glm::dvec2* FarUvByIdentity::uv(int k, rgbtest::Identity id, std::uint32_t base_face) const {
    if (k < 0 || k >= static_cast<int>(uv_.size())) return nullptr;
    const auto it = uv_[k].find({id, base_face});
    return it == uv_[k].end() ? nullptr : &it->second;
}

}  // namespace osdoracle
