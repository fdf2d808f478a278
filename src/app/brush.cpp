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
        case BrushMode::SetLevel: return BrushMode::SetLevel;
    }
    return mode;
}

rgb::LodDirection direction_of(BrushMode mode) {
    switch (mode) {
        case BrushMode::Refine: return rgb::LodDirection::Refine;
        case BrushMode::Coarsen: return rgb::LodDirection::Coarsen;
        case BrushMode::SetLevel: return rgb::LodDirection::Both;
    }
    return rgb::LodDirection::Both;
}

int target_at_distance(BrushMode mode, int target_level, float falloff, double d, double radius) {
    if (radius <= 0.0 || d > radius) return -1;
    const double band = std::clamp(static_cast<double>(falloff), 0.0, 1.0) * radius;
    // strength: 1 over the core, falling linearly to 0 at the rim.
    const double strength = band <= 0.0 ? 1.0 : std::clamp((radius - d) / band, 0.0, 1.0);
    switch (mode) {
        case BrushMode::Refine: return static_cast<int>(std::lround(strength * target_level));
        case BrushMode::Coarsen:
            return static_cast<int>(std::lround(target_level + (1.0 - strength) * (kMaxBrushLevel - target_level)));
        case BrushMode::SetLevel: return strength >= 1.0 ? target_level : -1;
    }
    return -1;
}

rgb::SetLevelStats apply_dab(rgb::Mesh& mesh, std::span<const rgb::FaceId> footprint, BrushMode mode,
                             const BrushSettings& settings, const glm::dvec3& centre, double radius) {
    const auto target_at = [&](const glm::dvec3& p) {
        return target_at_distance(mode, settings.target_level, settings.falloff, glm::distance(p, centre), radius);
    };
    return rgb::set_level_faces(mesh, footprint, target_at, direction_of(mode));
}

void grow_radius(BrushSettings& settings, int steps) {
    const float factor = std::pow(1.1f, static_cast<float>(steps));
    if (settings.unit == RadiusUnit::ScreenPixels)
        settings.radius_px = std::clamp(settings.radius_px * factor, 2.0f, 1000.0f);
    else
        settings.radius_world = std::clamp(settings.radius_world * factor, 1e-6f, 1e6f);
}

}  // namespace app
