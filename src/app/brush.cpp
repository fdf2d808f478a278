#include "app/brush.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace app {

BrushMode effective_mode(BrushMode mode, bool inverted) {
    if (!inverted) return mode;
    switch (mode) {
        case BrushMode::Refine: return BrushMode::Coarsen;
        case BrushMode::Coarsen: return BrushMode::Refine;
        case BrushMode::Set: return BrushMode::Set;
    }
    return mode;
}

int effective_level(const BrushSettings& settings, bool inverted) {
    return inverted && settings.mode == BrushMode::Refine ? 0 : settings.target_level;
}

BaseSpaceHit to_base_space(const rgb::Mesh& mesh, rgb::FaceId face, const std::array<glm::dvec3, 3>& displayed,
                           const glm::dvec3& point, double world_radius) {
    std::array<glm::dvec3, 3> base;
    for (int i = 0; i < 3; ++i) base[i] = mesh.base_space_position(mesh.face_vertices(face)[i]);
    // Barycentric coordinates of the point in the displayed triangle (by sub-triangle areas).
    const glm::dvec3 n = glm::cross(displayed[1] - displayed[0], displayed[2] - displayed[0]);
    const double nn = glm::dot(n, n);
    BaseSpaceHit hit;
    if (nn <= 0.0) {
        hit.centre = (base[0] + base[1] + base[2]) / 3.0;
    } else {
        const double w1 = glm::dot(glm::cross(point - displayed[0], displayed[2] - displayed[0]), n) / nn;
        const double w2 = glm::dot(glm::cross(displayed[1] - displayed[0], point - displayed[0]), n) / nn;
        hit.centre = (1.0 - w1 - w2) * base[0] + w1 * base[1] + w2 * base[2];
    }
    const double displayed_area = std::sqrt(nn);
    const double base_area = glm::length(glm::cross(base[1] - base[0], base[2] - base[0]));
    hit.radius = displayed_area > 0.0 ? world_radius * std::sqrt(base_area / displayed_area) : world_radius;
    return hit;
}

rgb::Dab make_dab(const BrushSettings& settings, bool inverted, const BaseSpaceHit& at, const glm::dvec3& view) {
    rgb::Dab dab;
    dab.mode = effective_mode(settings.mode, inverted);
    dab.level = effective_level(settings, inverted);
    dab.radius = at.radius;
    dab.falloff = settings.falloff;
    dab.centre = at.centre;
    if (!settings.paint_through) dab.view = view;
    return dab;
}

void grow_radius(BrushSettings& settings, int steps) {
    const float factor = std::pow(1.1f, static_cast<float>(steps));
    if (settings.unit == RadiusUnit::ScreenPixels)
        settings.radius_px = std::clamp(settings.radius_px * factor, kLeastRadiusPx, kMostRadiusPx);
    else
        settings.radius_world = std::clamp(settings.radius_world * factor, 1e-6f, 1e6f);
}

}  // namespace app
