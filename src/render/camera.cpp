#include "render/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace render {

// In double: squared distances of coordinates far from unit scale (1e-20, 1e12) leave float's range.
BoundingSphere bounding_sphere(std::span<const glm::vec3> points) {
    if (points.empty()) return {};
    glm::dvec3 lo = points.front();
    glm::dvec3 hi = points.front();
    for (const glm::vec3& p : points) {
        lo = glm::min(lo, glm::dvec3(p));
        hi = glm::max(hi, glm::dvec3(p));
    }
    const glm::dvec3 centre = 0.5 * (lo + hi);
    double radius = 0.0;
    for (const glm::vec3& p : points) radius = std::max(radius, glm::distance(glm::dvec3(p), centre));
    if (radius <= 0.0) radius = 1.0;  // a single point still needs a view
    return {glm::vec3(centre), static_cast<float>(radius)};
}

// The camera's matrices are made in double and rounded once: at extreme scales the normalisations
// inside lookAt and the products in perspective under- or overflow in float.
glm::dvec3 OrbitCamera::eye_double() const {
    const double az = glm::radians(static_cast<double>(azimuth_deg));
    const double el = glm::radians(static_cast<double>(elevation_deg));
    return glm::dvec3(target) + static_cast<double>(distance) * glm::dvec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
}

glm::vec3 OrbitCamera::eye() const { return glm::vec3(eye_double()); }

glm::dmat4 OrbitCamera::view_double() const {
    const double az = glm::radians(static_cast<double>(azimuth_deg));
    const glm::dvec3 eye = eye_double();
    // Up is derived from the azimuth's right vector, so looking straight down is well defined.
    const glm::dvec3 back = glm::normalize(eye - glm::dvec3(target));
    const glm::dvec3 right(std::cos(az), 0.0, -std::sin(az));
    return glm::lookAt(eye, glm::dvec3(target), glm::cross(back, right));
}

glm::mat4 OrbitCamera::view() const { return glm::mat4(view_double()); }

glm::dmat4 OrbitCamera::projection_double(float aspect) const {
    if (orthographic) {
        const double half_height = static_cast<double>(distance) * std::tan(0.5 * glm::radians(static_cast<double>(fov_y_deg)));
        const double half_width = half_height * static_cast<double>(aspect);
        return glm::ortho(-half_width, half_width, -half_height, half_height, static_cast<double>(near_plane), static_cast<double>(far_plane));
    }
    return glm::perspective(glm::radians(static_cast<double>(fov_y_deg)), static_cast<double>(aspect), static_cast<double>(near_plane),
                            static_cast<double>(far_plane));
}

glm::mat4 OrbitCamera::projection(float aspect) const { return glm::mat4(projection_double(aspect)); }

glm::mat4 OrbitCamera::view_projection(float aspect) const { return glm::mat4(projection_double(aspect) * view_double()); }

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

rgb::ScreenView screen_view(const OrbitCamera& camera, glm::ivec2 size) {
    rgb::ScreenView view;
    view.view_projection = glm::dmat4(camera.view_projection(static_cast<float>(size.x) / static_cast<float>(size.y)));
    view.viewport = glm::dvec2(size);
    view.eye = glm::dvec3(camera.eye());
    // A parallel view sees every face from the same direction: its eye (for what faces away) as far
    // back along it as makes no difference.
    if (camera.orthographic) view.eye = glm::dvec3(camera.target) + 1e6 * (view.eye - glm::dvec3(camera.target));
    return view;
}

}  // namespace render
