#include "support/oracle_surface.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "rgb/values/loop_geometry.h"

namespace rgbtest {

namespace {

using Bary = std::array<std::int64_t, 3>;  // barycentric numerators over the parent triangle

std::int64_t cross(const Bary& p, const Bary& q, const Bary& r) {
    return (q[1] - p[1]) * (r[2] - p[2]) - (q[2] - p[2]) * (r[1] - p[1]);
}

}  // namespace

const OracleSurface::Ring& OracleSurface::ring(Identity id) {
    const int level = oracle_.level(id);
    auto& level_rings = rings_[level];
    if (level_rings.empty()) {
        std::map<std::pair<Identity, Identity>, int> edge_faces;
        for (const IdentityTriangle& t : oracle_.faces(level))
            for (int i = 0; i < 3; ++i) {
                const Identity x = t[i], y = t[(i + 1) % 3];
                ++edge_faces[{std::min(x, y), std::max(x, y)}];
            }
        for (const auto& [edge, faces] : edge_faces)
            for (auto [x, y] : {edge, std::pair{edge.second, edge.first}}) {
                Ring& r = level_rings[x];
                r.neighbours.push_back(y);
                if (faces == 1) r.boundary.push_back(y);
            }
    }
    return level_rings.at(id);
}

glm::dvec3 OracleSurface::limit(Identity id) {
    if (const auto it = limits_.find(id); it != limits_.end()) return it->second;
    const int level = oracle_.level(id);
    const Ring& r = ring(id);
    const glm::dvec3 centre = oracle_.position(level, id);
    glm::dvec3 value;
    if (!r.boundary.empty()) {
        value = 2.0 / 3.0 * centre + (oracle_.position(level, r.boundary[0]) + oracle_.position(level, r.boundary[1])) / 6.0;
    } else {
        const double n = static_cast<double>(r.neighbours.size());
        const double t = 3.0 + 2.0 * std::cos(2.0 * std::numbers::pi / n);
        const double alpha = 5.0 / 8.0 - t * t / 64.0;
        const double c = 8.0 * alpha / (3.0 + 8.0 * alpha);
        glm::dvec3 sum(0.0);
        for (Identity w : r.neighbours) sum += oracle_.position(level, w);
        value = (1.0 - c) * centre + c / n * sum;
    }
    limits_.emplace(id, value);
    return value;
}

const std::vector<std::vector<std::size_t>>& OracleSurface::faces_at_vertices(int level) {
    auto& table = faces_at_vertex_[level];
    if (table.empty()) {
        table.resize(oracle_.num_identities(level));
        const auto& faces = oracle_.faces(level);
        for (std::size_t f = 0; f < faces.size(); ++f)
            for (Identity v : faces[f]) table[v].push_back(f);
    }
    return table;
}

IdentityTriangle OracleSurface::parent_triangle(const IdentityTriangle& face, int level) {
    // A corner of level <= l is a corner of the parent; every other corner is the midpoint of one
    // of the parent's edges.
    for (Identity low : face) {
        if (oracle_.level(low) > level) continue;
        for (std::size_t f : faces_at_vertices(level)[low]) {
            const IdentityTriangle& t = oracle_.faces(level)[f];
            bool all = true;
            for (Identity c : face) {
                bool found = c == t[0] || c == t[1] || c == t[2];
                for (int i = 0; i < 3 && !found; ++i) found = oracle_.midpoint(t[i], t[(i + 1) % 3]) == c;
                all = all && found;
            }
            if (all) return t;
        }
    }
    throw std::logic_error("oracle_surface: a face is no piece of a triangle of its level");
}

OracleError OracleSurface::displayed_error(const rgb::Mesh& mesh, const IdentityTracker& ids, int depth, Corners at) {
    OracleError out;
    const std::int64_t n = std::int64_t(1) << depth;
    for (rgb::FaceId f : mesh.faces()) {
        const int level = mesh.level(f);
        const IdentityTriangle face = ids.identity_triangle(f);
        const IdentityTriangle t = parent_triangle(face, level);
        // The points of Σ(level + depth) in t, by midpoint recursion from its corners.
        std::map<Bary, Identity> points{{{n, 0, 0}, t[0]}, {{0, n, 0}, t[1]}, {{0, 0, n}, t[2]}};
        std::vector<std::array<Bary, 3>> cells{{{{n, 0, 0}, {0, n, 0}, {0, 0, n}}}};
        for (int d = 0; d < depth; ++d) {
            std::vector<std::array<Bary, 3>> finer;
            for (const auto& c : cells) {
                std::array<Bary, 3> m;
                for (int i = 0; i < 3; ++i) {
                    const Bary &x = c[i], &y = c[(i + 1) % 3];
                    m[i] = {(x[0] + y[0]) / 2, (x[1] + y[1]) / 2, (x[2] + y[2]) / 2};
                    if (!points.count(m[i])) points[m[i]] = *oracle_.midpoint(points.at(x), points.at(y));
                }
                finer.push_back({c[0], m[0], m[2]});
                finer.push_back({m[0], c[1], m[1]});
                finer.push_back({m[2], m[1], c[2]});
                finer.push_back({m[0], m[1], m[2]});
            }
            cells.swap(finer);
        }
        // The face's corners over t, and where the mesh shows them.
        std::array<Bary, 3> corners;
        std::array<glm::dvec3, 3> shown;
        for (int c = 0; c < 3; ++c) {
            for (const auto& [b, id] : points)
                if (id == face[c]) corners[c] = b;
            const rgb::VertexId v = mesh.face_vertices(f)[c];
            shown[c] = at == Corners::Limit ? limit(face[c]) : oracle_.position(rgb::display_level(mesh, v), face[c]);
        }
        const std::int64_t area = cross(corners[0], corners[1], corners[2]);
        for (const auto& [q, id] : points) {
            const std::int64_t w0 = cross(q, corners[1], corners[2]), w1 = cross(corners[0], q, corners[2]),
                               w2 = cross(corners[0], corners[1], q);
            if (w0 < 0 || w1 < 0 || w2 < 0) continue;
            const glm::dvec3 at = (double(w0) * shown[0] + double(w1) * shown[1] + double(w2) * shown[2]) / double(area);
            out.max_error = std::max(out.max_error, glm::distance(at, limit(id)));
            out.deepest_level = std::max(out.deepest_level, oracle_.level(id));
            ++out.points;
        }
    }
    return out;
}

}  // namespace rgbtest
