#pragma once
// What a set of level requests means (docs/requests.md "What a request means"), computed independently of
// the core on the uniform Loop oracle's identities: the base-space position of every identity by
// midpoint recursion, the triangles of each Σj that meet a ball by their own distance test, the
// midpoints those triangles ask for, and the closure of that set under the RGB topology (a vertex on
// an edge of Σl needs the corners of both triangles of Σl at that edge).
#include <map>
#include <set>
#include <vector>

#include <glm/vec3.hpp>

#include "support/uniform_loop_oracle.h"

namespace rgbtest {

struct OracleBall {
    glm::dvec3 centre;
    double radius;
};

// Distance from p to the triangle (a, b, c) by a different route than the core's: the nearest point
// of the plane if it falls inside, else the nearest point of the three edges.
double oracle_distance_to_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

class RequestOracle {
public:
    explicit RequestOracle(const UniformLoopOracle& oracle);

    // The vertices a refine request for `level` in the ball asks for, with their closure.
    std::set<Identity> refined(const std::set<Identity>& current, int level, const OracleBall& ball) const;
    // The vertices left by a coarsen request: every vertex of level > `level` on an edge of a triangle
    // of Σj (j >= level) meeting the ball goes, with every vertex whose closure holds one of them.
    std::set<Identity> coarsened(const std::set<Identity>& current, int level, const OracleBall& ball) const;
    // The closure of a set of identities.
    std::set<Identity> closure(std::set<Identity> vertices) const;
    // The vertices of `current` whose closure holds none of `doomed`.
    std::set<Identity> without(const std::set<Identity>& current, const std::set<Identity>& doomed) const;
    // The ends of the edge the identity was inserted on (a base vertex: itself twice).
    std::pair<Identity, Identity> parents(Identity v) const { return parents_[v]; }
    // The base vertices alone.
    std::set<Identity> base() const;
    const glm::dvec3& base_space(Identity id) const { return base_space_[id]; }

private:
    // The triangles of Σl next to the edge v was inserted on.
    std::vector<IdentityTriangle> parent_triangles(Identity v) const;
    bool meets(const IdentityTriangle& t, const OracleBall& ball) const;

    const UniformLoopOracle& oracle_;
    std::vector<glm::dvec3> base_space_;
    std::vector<std::pair<Identity, Identity>> parents_;  // by identity; base vertices: themselves
    std::vector<std::map<std::pair<Identity, Identity>, std::vector<IdentityTriangle>>> edge_faces_;  // per level
};

}  // namespace rgbtest
