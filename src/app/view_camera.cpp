#include "app/view_camera.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

namespace app {
namespace {

constexpr float kDefaultAzimuthDeg = 30.0f;
constexpr float kDefaultElevationDeg = 20.0f;
constexpr float kOrbitDegPerPixel = 0.4f;
constexpr float kZoomFactorPerStep = 0.85f;

float aspect_of(glm::ivec2 viewport) {
    return static_cast<float>(std::max(viewport.x, 1)) / static_cast<float>(std::max(viewport.y, 1));
}

}  // namespace

void ViewCamera::frame(const render::BoundingSphere& scene, glm::ivec2 viewport) {
    scene_ = scene;
    const bool orthographic = camera_.orthographic;  // the projection is the user's choice, kept
    camera_ = render::frame_sphere(scene, kDefaultAzimuthDeg, kDefaultElevationDeg, aspect_of(viewport));
    camera_.orthographic = orthographic;
    fit_clip_planes();
}

void ViewCamera::refit(const render::BoundingSphere& scene, glm::ivec2 viewport) {
    scene_ = scene;
    const render::OrbitCamera framed =
        render::frame_sphere(scene, camera_.azimuth_deg, camera_.elevation_deg, aspect_of(viewport));
    camera_.target = framed.target;
    camera_.distance = framed.distance;
    fit_clip_planes();
}

void ViewCamera::orbit(glm::vec2 delta_px) {
    camera_.azimuth_deg = std::fmod(camera_.azimuth_deg - kOrbitDegPerPixel * delta_px.x, 360.0f);
    camera_.elevation_deg = std::clamp(camera_.elevation_deg + kOrbitDegPerPixel * delta_px.y, -89.0f, 89.0f);
}

void ViewCamera::pan(glm::vec2 delta_px, glm::ivec2 viewport) {
    const glm::mat4 view = camera_.view();
    // Rows of the view rotation are the camera's right and up axes in world space.
    const glm::vec3 right(view[0][0], view[1][0], view[2][0]);
    const glm::vec3 up(view[0][1], view[1][1], view[2][1]);
    const float scale = static_cast<float>(world_per_pixel(camera_.distance, viewport));
    camera_.target += scale * (-delta_px.x * right + delta_px.y * up);
    fit_clip_planes();
}

// Scaling the eye and the target about the anchor keeps the view direction, so the anchor stays on
// the same pixel.
void ViewCamera::zoom(float steps, const glm::dvec3& anchor) {
    const float wanted = std::clamp(camera_.distance * std::pow(kZoomFactorPerStep, steps), 1e-3f * scene_.radius, 100.0f * scene_.radius);
    const double factor = static_cast<double>(wanted) / static_cast<double>(camera_.distance);
    camera_.target = glm::vec3(anchor + (glm::dvec3(camera_.target) - anchor) * factor);
    camera_.distance = wanted;
    fit_clip_planes();
}

void ViewCamera::look_from(Axis axis) {
    struct Angles {
        float azimuth, elevation;
    };
    constexpr Angles kFrom[] = {{0.0f, 0.0f}, {180.0f, 0.0f}, {90.0f, 0.0f}, {-90.0f, 0.0f}, {0.0f, 90.0f}, {0.0f, -90.0f}};
    const Angles angles = kFrom[static_cast<int>(axis)];
    camera_.azimuth_deg = angles.azimuth;
    camera_.elevation_deg = angles.elevation;
    fit_clip_planes();
}

void ViewCamera::set_orthographic(bool on) {
    camera_.orthographic = on;
    fit_clip_planes();
}

// A parallel view sees what lies behind its eye too (zoomed in, the eye is inside the mesh), so its
// near plane may be negative.
void ViewCamera::fit_clip_planes() {
    const float reach = glm::distance(camera_.eye(), scene_.centre) + 1.5f * scene_.radius;
    camera_.far_plane = reach;
    camera_.near_plane = camera_.orthographic ? reach - 3.0f * scene_.radius : std::max(reach - 3.0f * scene_.radius, 1e-4f * reach);
}

Ray ViewCamera::ray_through(glm::vec2 px, glm::ivec2 viewport) const {
    const glm::dmat4 inverse = glm::inverse(glm::dmat4(camera_.view_projection(aspect_of(viewport))));
    const double x = 2.0 * (px.x + 0.5) / std::max(viewport.x, 1) - 1.0;
    const double y = 1.0 - 2.0 * (px.y + 0.5) / std::max(viewport.y, 1);
    const glm::dvec4 far_point = inverse * glm::dvec4(x, y, 1.0, 1.0);
    const glm::dvec3 far_end = glm::dvec3(far_point) / far_point.w;
    if (camera_.orthographic) {
        // Parallel rays, each from the near plane.
        const glm::dvec4 near_point = inverse * glm::dvec4(x, y, -1.0, 1.0);
        const glm::dvec3 near_end = glm::dvec3(near_point) / near_point.w;
        return {near_end, glm::normalize(far_end - near_end)};
    }
    const glm::dvec3 eye(camera_.eye());
    return {eye, glm::normalize(far_end - eye)};
}

double ViewCamera::world_per_pixel(double depth, glm::ivec2 viewport) const {
    const double half_fov = 0.5 * glm::radians(static_cast<double>(camera_.fov_y_deg));
    // A parallel view's pixel is as large at any depth as the perspective one's at the target.
    const double at = camera_.orthographic ? static_cast<double>(camera_.distance) : depth;
    return 2.0 * at * std::tan(half_fov) / std::max(viewport.y, 1);
}

double ViewCamera::depth_of(const glm::dvec3& p) const {
    const glm::dvec3 eye(camera_.eye());
    const glm::dvec3 forward = glm::normalize(glm::dvec3(camera_.target) - eye);
    return glm::dot(p - eye, forward);
}

}  // namespace app
