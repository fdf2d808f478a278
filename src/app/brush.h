#pragma once
// The level-of-detail brush (spec §3.4): what a dab asks of the engine, as a target level at each
// displayed position. GL-free.
#include <functional>

#include <glm/vec3.hpp>

#include "rgb/refine.h"

namespace app {

enum class BrushMode { Refine, Coarsen, SetLevel };
enum class RadiusUnit { ScreenPixels, World };

inline constexpr int kMaxBrushLevel = 8;

struct BrushSettings {
    BrushMode mode = BrushMode::Refine;
    int target_level = 3;
    RadiusUnit unit = RadiusUnit::ScreenPixels;
    float radius_px = 40.0f;
    float radius_world = 0.1f;
    // Fraction of the radius, from the rim inwards, over which the target tapers towards "no change".
    float falloff = 0.5f;
};

// Refine and coarsen swap while Shift is held; set-level is its own inverse.
BrushMode effective_mode(BrushMode mode, bool inverted);
rgb::LodDirection direction_of(BrushMode mode);

// The target level at distance `d` from the dab centre for a brush of world radius `radius`
// (negative: leave alone). Refine tapers from the target level at the core to 0 at the rim,
// coarsen from the target level up to kMaxBrushLevel, and set-level holds the target over the core
// and leaves the falloff band alone.
int target_at_distance(BrushMode mode, int target_level, float falloff, double d, double radius);

// One dab: the faces under the brush go to the engine. Returns what the engine did.
rgb::SetLevelStats apply_dab(rgb::Mesh& mesh, std::span<const rgb::FaceId> footprint, BrushMode mode,
                             const BrushSettings& settings, const glm::dvec3& centre, double radius);

// [ and ]: a tenth larger or smaller per press, within sensible limits, in the current unit.
void grow_radius(BrushSettings& settings, int steps);

}  // namespace app
