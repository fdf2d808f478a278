#include "rgb/lod/dab.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "rgb/mesh/base_face_index.h"
#include "rgb/mesh/mesh.h"
#include "rgb/support/triangle_geometry.h"

namespace rgb {

namespace {

// The part of the radius over which the level tapers, and the strength (1 over the core, falling to 0
// at the rim) at distance d.
double strength(double falloff, double d, double radius) {
    const double band = std::clamp(falloff, 0.0, 1.0) * radius;
    return band <= 0.0 ? 1.0 : std::clamp((radius - d) / band, 0.0, 1.0);
}

// Base-space points by x, then y, then z: an order that no storage changes.
bool position_less(const glm::dvec3& x, const glm::dvec3& y) {
    if (x.x != y.x) return x.x < y.x;
    if (x.y != y.y) return x.y < y.y;
    return x.z < y.z;
}

// Oriented normal (unnormalised), from the corners rotated to start at the lexicographically smallest,
// so that the input's corner rotation cannot flip a borderline facing test.
glm::dvec3 canonical_normal(std::array<glm::dvec3, 3> c) {
    const auto first = std::min_element(c.begin(), c.end(), position_less);
    std::rotate(c.begin(), first, c.end());
    return glm::cross(c[1] - c[0], c[2] - c[0]);
}

}  // namespace

int dab_level_at(BrushMode mode, int level, double falloff, double d, double radius) {
    if (radius <= 0.0 || d > radius) return -1;
    const double s = strength(falloff, d, radius);
    switch (mode) {
        case BrushMode::Refine: return static_cast<int>(std::lround(s * level));
        case BrushMode::Coarsen: return static_cast<int>(std::lround(level + (1.0 - s) * (kMaxLevel - level)));
        case BrushMode::Set: return s >= 1.0 ? level : -1;
    }
    return -1;
}

std::vector<std::uint32_t> facing_base_faces(const Mesh& mesh, const Sphere& ball, const glm::dvec3& view) {
    const BaseMesh& base = mesh.base();
    const std::vector<std::uint32_t> meeting = base.face_index().faces_meeting_sphere(ball.centre, ball.radius);
    auto in_ball = [&](std::uint32_t f) { return std::binary_search(meeting.begin(), meeting.end(), f); };
    auto facing = [&](std::uint32_t f) { return glm::dot(canonical_normal(base.corner_positions(f)), view) < 0.0; };
    // The hit: the facing base face nearest the centre; on an exact tie of distances (a centre on a
    // vertex or edge several facing faces share), the one with the least corners (sorted, compared by
    // x, y, z), not the least id, so that the input's face order cannot choose which faces are reached.
    std::optional<std::uint32_t> hit;
    double best = 0.0;
    std::array<glm::dvec3, 3> best_corners{};
    auto corners_less = [](const std::array<glm::dvec3, 3>& x, const std::array<glm::dvec3, 3>& y) {
        return std::lexicographical_compare(x.begin(), x.end(), y.begin(), y.end(), position_less);
    };
    for (std::uint32_t f : meeting) {
        if (!facing(f)) continue;
        auto c = base.corner_positions(f);
        std::sort(c.begin(), c.end(), position_less);
        const double d = distance_to_triangle(ball.centre, c[0], c[1], c[2]);
        if (!hit || d < best || (d == best && corners_less(c, best_corners))) {
            hit = f;
            best = d;
            best_corners = c;
        }
    }
    std::vector<std::uint32_t> reached;
    if (!hit) return reached;
    reached.push_back(*hit);
    for (std::size_t i = 0; i < reached.size(); ++i)
        for (std::uint32_t e = 0; e < 3; ++e) {
            const std::uint32_t o = base.opposite(3 * reached[i] + e);
            if (o == BaseMesh::kNone) continue;
            const std::uint32_t g = o / 3;
            if (in_ball(g) && facing(g) && std::find(reached.begin(), reached.end(), g) == reached.end()) reached.push_back(g);
        }
    std::sort(reached.begin(), reached.end());
    return reached;
}

LevelRequest dab_request(const Mesh& mesh, const Dab& dab) {
    LevelRequest r;
    r.sphere = Sphere{dab.centre, dab.radius};
    r.level = dab.level;
    const double band = std::clamp(dab.falloff, 0.0, 1.0) * dab.radius;
    switch (dab.mode) {
        case BrushMode::Set:
            r.kind = RequestKind::Set;
            r.sphere->radius = dab.radius - band;
            break;
        case BrushMode::Refine:
            // dab_level_at >= k exactly within R - band (k - 1/2) / N (lround rounds halves up).
            r.kind = RequestKind::Refine;
            r.sphere->radius = dab.radius - band * (dab.level - 0.5) / std::max(dab.level, 1);
            if (band > 0.0)
                for (int k = 1; k < dab.level; ++k) r.taper.push_back({k, dab.radius - band * (k - 0.5) / dab.level});
            break;
        case BrushMode::Coarsen:
            // dab_level_at <= k within R - band (1 - (k + 1/2 - N) / (kMaxLevel - N)).
            r.kind = RequestKind::Coarsen;
            r.sphere->radius = dab.radius - band * (1.0 - 0.5 / std::max(kMaxLevel - dab.level, 1));
            if (band > 0.0)
                for (int k = dab.level + 1; k < kMaxLevel; ++k)
                    r.taper.push_back({k, dab.radius - band * (1.0 - (k + 0.5 - dab.level) / (kMaxLevel - dab.level))});
            break;
    }
    if (dab.view) r.base_faces = facing_base_faces(mesh, Sphere{dab.centre, dab.radius}, *dab.view);
    return r;
}

RequestStats apply_dab(Mesh& mesh, const Dab& dab) {
    if (dab.view && !(glm::length(*dab.view) > 0.0)) return {};
    const LevelRequest r = dab_request(mesh, dab);
    if (r.sphere->radius <= 0.0 || (dab.view && r.base_faces.empty())) return {};
    if (dab.mode == BrushMode::Refine && dab.level == 0) return {};
    return apply_request(mesh, r);
}

}  // namespace rgb
