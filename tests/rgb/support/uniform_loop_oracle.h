#pragma once
// A plain uniform Loop subdivision (original weights, spec §4.1), written independently of src/rgb:
// its own adjacency, no closed forms, one explicit one-to-four step per level. Vertices are keyed by
// identity: base vertex i is identity i; the vertex inserted on the edge {x, y} is the identity
// midpoint(x, y), the same at every later level. Identities are numbered level by level, so the
// vertices of Σk are exactly the identities below num_identities(k).
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <unordered_map>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh/mesh.h"

namespace rgbtest {

using Identity = std::uint32_t;
using IdentityTriangle = std::array<Identity, 3>;

class UniformLoopOracle {
public:
    // Computes Σ0 .. Σlevels. Throws std::invalid_argument if an edge has more than two faces.
    UniformLoopOracle(std::span<const glm::dvec3> positions, std::span<const rgb::Triangle> triangles, int levels);

    int levels() const { return static_cast<int>(levels_.size()) - 1; }
    std::size_t num_identities(int k) const { return levels_[k].positions.size(); }
    // p^k of the identity; requires level(id) <= k <= levels().
    const glm::dvec3& position(int k, Identity id) const { return levels_[k].positions[id]; }
    // Faces of Σk, counter-clockwise, each rotated to start at its smallest identity.
    const std::vector<IdentityTriangle>& faces(int k) const { return levels_[k].faces; }
    // Whether t (in any rotation, same orientation) is a face of Σk.
    bool has_face(int k, const IdentityTriangle& t) const;
    // The identity inserted on the edge {a, b} of some Σk, if the oracle went that far.
    std::optional<Identity> midpoint(Identity a, Identity b) const;
    // The level at which the identity first appears.
    int level(Identity id) const { return identity_level_[id]; }

private:
    struct Level {
        std::vector<glm::dvec3> positions;    // by identity
        std::vector<IdentityTriangle> faces;  // canonical rotation, sorted
    };
    void subdivide_once();
    Identity new_midpoint(Identity a, Identity b);

    std::vector<Level> levels_;
    std::unordered_map<std::uint64_t, Identity> midpoints_;
    std::vector<int> identity_level_;
};

}  // namespace rgbtest
