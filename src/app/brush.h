#pragma once
// The level-of-detail brush as the editor holds it: a mode, a target level, a radius in screen pixels
// or world units, a falloff. A dab becomes an rgb::Dab in base space (rgb/lod/dab.h), the same request a
// recorded stroke replays. GL-free.
#include <cstdint>

#include <glm/vec3.hpp>

#include "rgb/lod/dab.h"
#include "rgb/mesh/mesh.h"

namespace app {

using BrushMode = rgb::BrushMode;
enum class RadiusUnit { ScreenPixels, World };

// The finest level the brush and "Set all" offer (the core accepts up to rgb::kMaxLevel).
inline constexpr int kMaxBrushLevel = 12;
// The screen radii the brush takes.
inline constexpr float kLeastRadiusPx = 2.0f;
inline constexpr float kMostRadiusPx = 1000.0f;
// The stroke spacing and the lazy mouse's string offered (BrushSettings).
inline constexpr float kLeastDabsPerRadius = 0.5f;
inline constexpr float kMostDabsPerRadius = 20.0f;
inline constexpr float kMostLazyPx = 200.0f;

struct BrushSettings {
    BrushMode mode = BrushMode::Refine;
    int target_level = 3;
    RadiusUnit unit = RadiusUnit::ScreenPixels;
    float radius_px = 40.0f;
    float radius_world = 0.1f;
    // Fraction of the radius, from the rim inwards, over which the target tapers towards "no change".
    float falloff = 0.5f;
    // Paint only faces facing the camera and connected to the hit through the surface.
    bool paint_through = false;
    // What a dab asks for: the target level, a detail size or a tolerance (docs/requests.md "Detail by size,
    // accuracy and view"): no green edge longer than the size, or the surface shown within the
    // tolerance of the limit surface at its samples, in the ball, as coarse as the criterion allows (set; refine only adds, coarsen
    // only removes); the amount in screen pixels where the dab lands (relative detail) or in the
    // mesh's units (constant detail). Such dabs have no falloff and paint through.
    enum class Target { Level, DetailSize, Tolerance } target = Target::Level;
    RadiusUnit detail_unit = RadiusUnit::ScreenPixels;
    float detail_px = 6.0f;
    float detail_world = 0.01f;
    // Symmetric painting: every dab with its mirror images across these planes of the mesh's own
    // frame (rgbio::kMirrorX | kMirrorY | kMirrorZ; rgbio::with_mirror_images).
    std::uint8_t mirror = 0;
    // Stroke spacing: dabs per brush radius along the stroke (4: a dab every quarter radius, which
    // overlaps enough to leave no gaps).
    float dabs_per_radius = 4.0f;
    // Lazy mouse: the brush trails the pointer on a string this many screen pixels long, moving
    // only when the pointer pulls it, so that hand jitter smaller than that leaves a smooth stroke
    // (0: off). The string shows on screen while painting.
    float lazy_px = 0.0f;
    bool operator==(const BrushSettings&) const = default;
};

// Shift inverts: refine becomes coarsen down to the base level (so it always removes what refining
// added), coarsen becomes refine to the target; set-level is its own inverse.
BrushMode effective_mode(BrushMode mode, bool inverted);
int effective_level(const BrushSettings& settings, bool inverted);

// Where the brush touched the displayed surface, mapped to base space: the hit face's corners in
// base space weighted like the hit point in the displayed triangle, and the world radius scaled by
// that face's size in base space over its displayed size.
struct BaseSpaceHit {
    glm::dvec3 centre{0.0};
    double radius = 0.0;
};
BaseSpaceHit to_base_space(const rgb::Mesh& mesh, rgb::FaceId face, const std::array<glm::dvec3, 3>& displayed,
                           const glm::dvec3& point, double world_radius);

rgb::Dab make_dab(const BrushSettings& settings, bool inverted, const BaseSpaceHit& at, const glm::dvec3& view);

// [ and ]: a tenth larger or smaller per press, within sensible limits, in the current unit.
void grow_radius(BrushSettings& settings, int steps);

}  // namespace app
