#include "support/oracle_limit.h"

#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>

namespace rgbtest {

glm::dvec3 oracle_limit(const UniformLoopOracle& oracle, const rgb::Mesh& mesh, rgb::VertexId v) {
    const int level = mesh.level(v);
    const glm::dvec3 p = mesh.insertion_position(v);
    Identity id = 0;
    double best = 1e300;
    for (Identity i = 0; i < oracle.num_identities(level); ++i) {
        if (oracle.level(i) != level) continue;
        const double d = glm::distance(oracle.position(level, i), p);
        if (d < best) {
            best = d;
            id = i;
        }
    }
    if (best > 1e-9) throw std::logic_error("oracle_limit: the vertex is not in the oracle");
    // Its ring in Σ(level), and which of its edges have one face only (the boundary).
    std::map<Identity, int> edge_faces;
    for (const IdentityTriangle& t : oracle.faces(level))
        for (int i = 0; i < 3; ++i) {
            if (t[i] == id) ++edge_faces[t[(i + 1) % 3]];
            if (t[(i + 1) % 3] == id) ++edge_faces[t[i]];
        }
    std::vector<Identity> ring, boundary;
    for (const auto& [w, faces] : edge_faces) {
        ring.push_back(w);
        if (faces == 1) boundary.push_back(w);
    }
    const glm::dvec3 centre = oracle.position(level, id);
    if (!boundary.empty())
        return 2.0 / 3.0 * centre + (oracle.position(level, boundary[0]) + oracle.position(level, boundary[1])) / 6.0;
    const double n = static_cast<double>(ring.size());
    const double t = 3.0 + 2.0 * std::cos(2.0 * std::numbers::pi / n);
    const double alpha = 5.0 / 8.0 - t * t / 64.0;
    const double c = 8.0 * alpha / (3.0 + 8.0 * alpha);
    glm::dvec3 sum(0.0);
    for (Identity w : ring) sum += oracle.position(level, w);
    return (1.0 - c) * centre + c / n * sum;
}

}  // namespace rgbtest
