#include "app/surface_picking.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "render/surface_geometry.h"
#include "rgb/mesh.h"

namespace app {
namespace {

std::array<glm::dvec3, 3> corners(const render::SurfaceGeometry& geometry, rgb::FaceId f) {
    const std::span<const render::SurfaceVertex> v = geometry.vertices();
    return {glm::dvec3(v[3 * f.idx].position), glm::dvec3(v[3 * f.idx + 1].position),
            glm::dvec3(v[3 * f.idx + 2].position)};
}

bool slot_is_live(const render::SurfaceGeometry& geometry, std::uint32_t slot) {
    return (geometry.vertices()[3 * slot].code & render::kCodeLiveBit) != 0;
}

// Möller–Trumbore, front faces only (counter-clockwise as seen from the ray origin).
std::optional<double> front_hit(const Ray& ray, const std::array<glm::dvec3, 3>& t) {
    const glm::dvec3 e1 = t[1] - t[0];
    const glm::dvec3 e2 = t[2] - t[0];
    const glm::dvec3 p = glm::cross(ray.direction, e2);
    const double det = glm::dot(e1, p);
    if (det <= 0.0) return std::nullopt;  // back facing or parallel
    const glm::dvec3 s = ray.origin - t[0];
    const double u = glm::dot(s, p) / det;
    if (u < 0.0 || u > 1.0) return std::nullopt;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(ray.direction, q) / det;
    if (v < 0.0 || u + v > 1.0) return std::nullopt;
    const double distance = glm::dot(e2, q) / det;
    if (distance <= 0.0) return std::nullopt;
    return distance;
}

void consider(const render::SurfaceGeometry& geometry, const Ray& ray, rgb::FaceId f, std::optional<SurfaceHit>& best) {
    const std::optional<double> distance = front_hit(ray, corners(geometry, f));
    if (distance && (!best || *distance < best->distance))
        best = SurfaceHit{f, ray.origin + *distance * ray.direction, *distance};
}

}  // namespace

double distance_to_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    // Closest point by Voronoi regions (Ericson, Real-Time Collision Detection §5.1.5).
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return glm::distance(p, a);
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return glm::distance(p, b);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return glm::distance(p, a + ab * (d1 / (d1 - d3)));
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return glm::distance(p, c);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return glm::distance(p, a + ac * (d2 / (d2 - d6)));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
        return glm::distance(p, b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
    const double denom = 1.0 / (va + vb + vc);
    return glm::distance(p, a + ab * (vb * denom) + ac * (vc * denom));
}

std::optional<SurfaceHit> pick_surface(const render::SurfaceGeometry& geometry, const Ray& ray) {
    std::optional<SurfaceHit> best;
    const auto slots = static_cast<std::uint32_t>(geometry.face_slots());
    for (std::uint32_t slot = 0; slot < slots; ++slot)
        if (slot_is_live(geometry, slot)) consider(geometry, ray, rgb::FaceId(slot), best);
    return best;
}

std::vector<rgb::FaceId> faces_in_sphere(const rgb::Mesh& mesh, const render::SurfaceGeometry& geometry,
                                         rgb::FaceId seed, const glm::dvec3& centre, double radius) {
    std::vector<rgb::FaceId> found;
    if (!mesh.is_live(seed) || seed.idx >= geometry.face_slots()) return found;
    // Visited marks live for one call; a small sorted set would cost a log per face, this is O(1).
    thread_local std::vector<std::uint32_t> visited_stamp;
    thread_local std::uint32_t stamp = 0;
    if (visited_stamp.size() < mesh.face_capacity()) visited_stamp.resize(mesh.face_capacity(), 0);
    if (++stamp == 0) {
        std::fill(visited_stamp.begin(), visited_stamp.end(), 0);
        stamp = 1;
    }
    found.push_back(seed);
    visited_stamp[seed.idx] = stamp;
    for (std::size_t next = 0; next < found.size(); ++next) {
        const rgb::FaceId f = found[next];
        for (int i = 0; i < 3; ++i) {
            const rgb::HalfedgeId opposite = mesh.opposite(rgb::Mesh::halfedge(f, i));
            if (!opposite.valid()) continue;
            const rgb::FaceId g = rgb::Mesh::face(opposite);
            if (visited_stamp[g.idx] == stamp) continue;
            visited_stamp[g.idx] = stamp;
            const auto t = corners(geometry, g);
            if (distance_to_triangle(centre, t[0], t[1], t[2]) <= radius) found.push_back(g);
        }
    }
    return found;
}

std::optional<SurfaceHit> pick_surface_near(const rgb::Mesh& mesh, const render::SurfaceGeometry& geometry,
                                            const Ray& ray, rgb::FaceId seed, const glm::dvec3& near, double reach) {
    std::optional<SurfaceHit> best;
    for (rgb::FaceId f : faces_in_sphere(mesh, geometry, seed, near, reach)) consider(geometry, ray, f, best);
    return best;
}

}  // namespace app
