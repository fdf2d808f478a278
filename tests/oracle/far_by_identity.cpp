#include "far_by_identity.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "rgb/values/loop_geometry.h"
#include "support/oracle_checks.h"
#include "support/test_meshes.h"

namespace osdoracle {

rgb::SharpFeatures sharp_features_of(const FarInput& input) {
    rgb::SharpFeatures f;
    for (const SharpEdge& e : input.creases)
        f.edges.push_back({static_cast<std::uint32_t>(e.a), static_cast<std::uint32_t>(e.b), static_cast<int>(e.sharpness)});
    for (const SharpVertex& c : input.corners)
        f.corners.push_back({static_cast<std::uint32_t>(c.vertex), static_cast<int>(c.sharpness)});
    f.boundary = input.boundary == BoundaryInterpolation::edge_and_corner ? rgb::BoundaryInterpolation::EdgeAndCorner
                                                                          : rgb::BoundaryInterpolation::EdgeOnly;
    return f;
}

std::vector<rgb::Triangle> rgb_triangles(const FarInput& input) {
    std::vector<rgb::Triangle> t;
    for (const auto& x : input.triangles)
        t.push_back({static_cast<std::uint32_t>(x[0]), static_cast<std::uint32_t>(x[1]), static_cast<std::uint32_t>(x[2])});
    return t;
}

std::shared_ptr<const rgb::BaseMesh> tagged_base(const FarInput& input) {
    return std::make_shared<const rgb::BaseMesh>(input.positions, rgb_triangles(input), sharp_features_of(input));
}

std::vector<std::vector<rgbtest::Identity>> identities_of(const FarRefinement& far, const rgbtest::UniformLoopOracle& oracle) {
    std::vector<std::vector<rgbtest::Identity>> identities(1);
    for (std::size_t v = 0; v < far.levels[0].positions.size(); ++v) identities[0].push_back(static_cast<rgbtest::Identity>(v));
    for (std::size_t k = 1; k < far.levels.size(); ++k) {
        const std::vector<rgbtest::Identity>& coarse = identities.back();
        std::vector<rgbtest::Identity> finer;
        for (const VertexOrigin& o : far.levels[k].origins)
            finer.push_back(o.on_edge ? oracle.midpoint(coarse[o.a], coarse[o.b]).value() : coarse[o.a]);
        identities.push_back(std::move(finer));
    }
    return identities;
}

FarByIdentity::FarByIdentity(const FarInput& input, int levels)
    : oracle_(input.positions, rgb_triangles(input), levels),
      far_(refine_uniform(input, levels)),
      tolerance_(1e-12 * rgbtest::bounding_box_diagonal(input.positions)) {
    const std::vector<std::vector<rgbtest::Identity>> identities = identities_of(far_, oracle_);
    for (int k = 0; k <= levels; ++k) {
        const FarLevel& level = far_.levels[k];
        const std::vector<rgbtest::Identity>& identity = identities[k];
        if (level.positions.size() != oracle_.num_identities(k)) throw std::logic_error("Far and the oracle disagree on Σk");
        std::vector<glm::dvec3> by_identity(level.positions.size());
        std::vector<int> index(level.positions.size());
        for (std::size_t v = 0; v < level.positions.size(); ++v) {
            by_identity[identity[v]] = level.positions[v];
            index[identity[v]] = static_cast<int>(v);
        }
        positions_.push_back(std::move(by_identity));
        far_index_.push_back(std::move(index));
    }
}

testing::AssertionResult agrees_with_far(const rgb::Mesh& mesh, const rgbtest::IdentityTracker& ids,
                                         const FarByIdentity& far, double* worst) {
    double largest = 0.0;
    for (rgb::VertexId v : mesh.vertices()) {
        const rgbtest::Identity id = ids.identity(v);
        if (id == rgbtest::IdentityTracker::kNone) return testing::AssertionFailure() << "vertex " << v.idx << " has no identity";
        const int own = mesh.level(v), shown = rgb::display_level(mesh, v);
        if (shown > far.levels()) return testing::AssertionFailure() << "vertex " << v.idx << " shown beyond Far's levels";
        const struct {
            const char* what;
            int level;
            glm::dvec3 value;
        } checks[] = {{"insertion position", own, mesh.insertion_position(v)},
                      {"displayed position", shown, rgb::displayed_position(mesh, v)}};
        for (const auto& c : checks) {
            const double error = glm::distance(c.value, far.position(c.level, id));
            largest = std::max(largest, error);
            if (!(error <= far.tolerance()))
                return testing::AssertionFailure() << c.what << " of vertex " << v.idx << " (identity " << id << ", level "
                                                   << own << ") at level " << c.level << " is " << error
                                                   << " from Far's";
        }
    }
    const rgbtest::OracleView view{mesh, ids, far.tolerance()};
    for (rgb::FaceId f : mesh.faces())
        if (auto r = rgbtest::face_agrees(view, f); !r) return r;
    if (worst) *worst = std::max(*worst, largest);
    return testing::AssertionSuccess();
}

}  // namespace osdoracle
