#pragma once
// Orbit camera and automatic framing. GL-free math (GLM only), shared by the editor and the
// headless renderer. Conventions: Y is up; azimuth 0 looks from +Z towards -Z, positive azimuth
// turns the eye towards +X; elevation 90 looks straight down.
#include <span>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "rgb/lod/screen_detail.h"

namespace render {

struct BoundingSphere {
    glm::vec3 centre{0.0f};
    float radius = 1.0f;
};

// Centre of the bounding box and the largest distance from it (computed in double, so any float
// scale works); radius 1 around the origin if empty or a single point.
BoundingSphere bounding_sphere(std::span<const glm::vec3> points);

struct OrbitCamera {
    glm::vec3 target{0.0f};
    float distance = 3.0f;
    float azimuth_deg = 30.0f;
    float elevation_deg = 20.0f;
    float fov_y_deg = 35.0f;
    float near_plane = 0.01f;
    float far_plane = 100.0f;
    // Parallel projection, as large as the perspective one at the target (so toggling it keeps what
    // is at the target's depth the same size on screen).
    bool orthographic = false;

    glm::vec3 eye() const;
    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;
    glm::mat4 view_projection(float aspect) const;

private:
    glm::dvec3 eye_double() const;
    glm::dmat4 view_double() const;
    glm::dmat4 projection_double(float aspect) const;
};

// A camera at the given angles whose view cone contains the sphere (with a small margin) for a
// viewport of the given aspect ratio (width / height).
OrbitCamera frame_sphere(const BoundingSphere& sphere, float azimuth_deg, float elevation_deg, float aspect);

// The camera as the core's screen-space criterion sees it, for a viewport of `size` pixels.
rgb::ScreenView screen_view(const OrbitCamera& camera, glm::ivec2 size);

// Fraction of the view cone's half-angle the framed sphere fills.
inline constexpr float kFramingMargin = 1.1f;

}  // namespace render
