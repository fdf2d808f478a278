#pragma once
// A tagged Far refinement seen through the identities of the uniform Loop oracle (tests/rgb/support),
// so an adaptive RGB mesh's vertices (followed by an IdentityTracker) can be compared with Far's
// vertex of the same level: Far's vertex origins are chained down to the base as in
// uniform_agreement_test.cpp. The oracle serves only for the identities and the faces of each level
// (the topology does not depend on tags); positions are Far's.
#include <memory>
#include <vector>

#include <glm/vec3.hpp>
#include <gtest/gtest.h>

#include "osd_far.h"
#include "rgb/mesh/base_mesh.h"
#include "rgb/mesh/mesh.h"
#include "support/identity_tracker.h"
#include "support/uniform_loop_oracle.h"

namespace osdoracle {

// The Far input's tags as the core's (integer sharpness: the cases use integers only).
rgb::SharpFeatures sharp_features_of(const FarInput& input);
std::vector<rgb::Triangle> rgb_triangles(const FarInput& input);
// The tagged base mesh the core refines.
std::shared_ptr<const rgb::BaseMesh> tagged_base(const FarInput& input);
// [k][v]: the oracle's identity of Far's vertex v of level k, by chaining Far's vertex origins.
std::vector<std::vector<rgbtest::Identity>> identities_of(const FarRefinement& far, const rgbtest::UniformLoopOracle& oracle);

class FarByIdentity {
public:
    FarByIdentity(const FarInput& input, int levels);

    const rgbtest::UniformLoopOracle& oracle() const { return oracle_; }
    int levels() const { return static_cast<int>(positions_.size()) - 1; }
    // Far's p^k of the vertex with this identity (level(id) <= k <= levels()).
    const glm::dvec3& position(int k, rgbtest::Identity id) const { return positions_[k][id]; }
    double tolerance() const { return tolerance_; }  // 1e-12 of the base bounding-box diagonal
    const FarRefinement& refinement() const { return far_; }
    // Far's index of the vertex with this identity in level k.
    int far_index(int k, rgbtest::Identity id) const { return far_index_[k][id]; }

private:
    rgbtest::UniformLoopOracle oracle_;
    FarRefinement far_;
    std::vector<std::vector<int>> far_index_;         // [level][identity]
    std::vector<std::vector<glm::dvec3>> positions_;  // [level][identity]
    double tolerance_;
};

// Every live vertex's insertion position is Far's vertex at its own level and its displayed position
// Far's vertex at its display level; every green face is a face of its level. `worst` (if given)
// receives the largest distance seen.
testing::AssertionResult agrees_with_far(const rgb::Mesh& mesh, const rgbtest::IdentityTracker& ids,
                                         const FarByIdentity& far, double* worst = nullptr);

}  // namespace osdoracle
