#pragma once
// The displayed surface of an adaptive mesh against the Loop limit surface, measured on the uniform
// Loop oracle and so independently of the core's geometry: every face of level l is located in the
// oracle's Σl as a piece of one of its triangles (spec §1.3), the points of Σ(l+depth) in that piece
// are found by midpoint recursion over the oracle's identities, the displayed surface there is the
// flat face between its corners at the oracle's positions of their display levels, and the limit
// point is Loop's limit mask (with its own weights) applied to the point's ring in the oracle.
#include <map>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh/mesh.h"
#include "support/identity_tracker.h"
#include "support/uniform_loop_oracle.h"

namespace rgbtest {

struct OracleError {
    double max_error = 0.0;
    std::size_t points = 0;
    int deepest_level = 0;  // of the points measured
};

class OracleSurface {
public:
    explicit OracleSurface(const UniformLoopOracle& oracle) : oracle_(oracle) {}

    // p^inf of the identity from its ring in the oracle's mesh of its level.
    glm::dvec3 limit(Identity id);
    // Where the flat faces' corners are: at their display levels' positions, or at their limits (the
    // positions `rgbsub lods` writes).
    enum class Corners { Displayed, Limit };
    // Over the points of Σ(l + depth) in each face of level l; needs l + depth <= the oracle's levels.
    OracleError displayed_error(const rgb::Mesh& mesh, const IdentityTracker& ids, int depth, Corners at = Corners::Displayed);

private:
    struct Ring {
        std::vector<Identity> neighbours, boundary;
    };
    const Ring& ring(Identity id);
    // The triangle of Σl whose corners and edge midpoints are the face's corners.
    IdentityTriangle parent_triangle(const IdentityTriangle& face, int level);
    const std::vector<std::vector<std::size_t>>& faces_at_vertices(int level);

    const UniformLoopOracle& oracle_;
    std::map<int, std::map<Identity, Ring>> rings_;                       // by level, built per level
    std::map<int, std::vector<std::vector<std::size_t>>> faces_at_vertex_;  // by level: identity -> faces of Σl
    std::map<Identity, glm::dvec3> limits_;
};

}  // namespace rgbtest
