#include "render/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace render {

BoundingSphere bounding_sphere(std::span<const glm::vec3> points) {
    if (points.empty()) return {};
    glm::vec3 lo = points.front();
    glm::vec3 hi = points.front();
    for (const glm::vec3& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    BoundingSphere sphere{0.5f * (lo + hi), 0.0f};
    for (const glm::vec3& p : points) sphere.radius = std::max(sphere.radius, glm::distance(p, sphere.centre));
    if (sphere.radius <= 0.0f) sphere.radius = 1.0f;  // a single point still needs a view
    return sphere;
}

glm::vec3 OrbitCamera::eye() const {
    const float az = glm::radians(azimuth_deg);
    const float el = glm::radians(elevation_deg);
    return target + distance * glm::vec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
}

glm::mat4 OrbitCamera::view() const {
    const float az = glm::radians(azimuth_deg);
    // Up is derived from the azimuth's right vector, so looking straight down is well defined.
    const glm::vec3 back = glm::normalize(eye() - target);
    const glm::vec3 right(std::cos(az), 0.0f, -std::sin(az));
    return glm::lookAt(eye(), target, glm::cross(back, right));
}

glm::mat4 OrbitCamera::projection(float aspect) const {
    return glm::perspective(glm::radians(fov_y_deg), aspect, near_plane, far_plane);
}

OrbitCamera frame_sphere(const BoundingSphere& sphere, float azimuth_deg, float elevation_deg, float aspect) {
    OrbitCamera camera;
    camera.target = sphere.centre;
    camera.azimuth_deg = azimuth_deg;
    camera.elevation_deg = elevation_deg;
    const float half_y = 0.5f * glm::radians(camera.fov_y_deg);
    const float half_x = std::atan(std::tan(half_y) * aspect);
    const float half = std::min(half_x, half_y) / kFramingMargin;
    camera.distance = sphere.radius / std::sin(half);
    camera.near_plane = std::max(camera.distance - 1.5f * sphere.radius, 1e-3f * camera.distance);
    camera.far_plane = camera.distance + 1.5f * sphere.radius;
    return camera;
}

}  // namespace render
