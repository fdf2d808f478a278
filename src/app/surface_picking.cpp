#include "app/surface_picking.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "render/surface_geometry.h"
#include "rgb/mesh.h"
#include "rgb/triangle_geometry.h"

namespace app {
namespace {

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
    const std::optional<double> distance = front_hit(ray, geometry.corners(f));
    if (distance && (!best || *distance < best->distance))
        best = SurfaceHit{f, ray.origin + *distance * ray.direction, *distance};
}

}  // namespace

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
            const auto t = geometry.corners(g);
            if (rgb::distance_to_triangle(centre, t[0], t[1], t[2]) <= radius) found.push_back(g);
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
