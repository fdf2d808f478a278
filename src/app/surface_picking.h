#pragma once
// What the brush touches on the displayed surface (spec §3.4): the front-facing triangle a ray hits
// first. SurfaceIndex (surface_index.h) finds the candidates; this is the test of one triangle.
#include <array>
#include <optional>

#include <glm/vec3.hpp>

#include "app/view_camera.h"
#include "rgb/mesh/handles.h"

namespace app {

struct SurfaceHit {
    rgb::FaceId face;
    glm::dvec3 point{0.0};
    double distance = 0.0;  // along the ray
};

// Möller–Trumbore, front faces only (counter-clockwise as seen from the ray's origin): the distance
// along the ray, if it hits.
std::optional<double> front_hit(const Ray& ray, const std::array<glm::dvec3, 3>& triangle);

}  // namespace app
