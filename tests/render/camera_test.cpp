// Automatic framing: every point of the bounding sphere lands inside the viewport.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec4.hpp>

#include "render/camera.h"

namespace {

using render::BoundingSphere;

TEST(Camera, BoundingSphereContainsEveryPoint) {
    const std::vector<glm::vec3> points{{1, 2, 3}, {-1, 0, 5}, {4, -2, 1}, {0, 0, 0}};
    const BoundingSphere sphere = render::bounding_sphere(points);
    EXPECT_EQ(sphere.centre, glm::vec3(1.5f, 0.0f, 2.5f));  // the box [-1,4] x [-2,2] x [0,5]
    for (const glm::vec3& p : points) EXPECT_LE(glm::distance(p, sphere.centre), sphere.radius + 1e-6f);
}

TEST(Camera, FramedSphereFitsTheViewportFromEveryAngle) {
    const BoundingSphere sphere{{0.5f, -2.0f, 3.0f}, 2.5f};
    for (float aspect : {0.5f, 1.0f, 4.0f / 3.0f, 2.0f})
        for (float elevation : {-90.0f, -30.0f, 0.0f, 45.0f, 90.0f})
            for (float azimuth : {0.0f, 30.0f, 135.0f, 270.0f}) {
                const render::OrbitCamera camera = render::frame_sphere(sphere, azimuth, elevation, aspect);
                const glm::mat4 vp = camera.view_projection(aspect);
                // Points of the sphere along the axes and diagonals.
                for (int i = 0; i < 27; ++i) {
                    const glm::vec3 d(i % 3 - 1, (i / 3) % 3 - 1, i / 9 - 1);
                    if (d == glm::vec3(0.0f)) continue;
                    const glm::vec4 clip = vp * glm::vec4(sphere.centre + sphere.radius * glm::normalize(d), 1.0f);
                    ASSERT_GT(clip.w, 0.0f);
                    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
                    EXPECT_LT(std::abs(ndc.x), 1.0f) << "azimuth " << azimuth << " elevation " << elevation << " aspect " << aspect;
                    EXPECT_LT(std::abs(ndc.y), 1.0f);
                    EXPECT_GT(ndc.z, -1.0f);
                    EXPECT_LT(ndc.z, 1.0f);
                }
            }
}

TEST(Camera, ElevationNinetyLooksStraightDown) {
    render::OrbitCamera camera;
    camera.elevation_deg = 90.0f;
    const glm::vec3 eye = camera.eye();
    EXPECT_NEAR(eye.x, 0.0f, 1e-5f);
    EXPECT_NEAR(eye.y, camera.distance, 1e-5f);
    EXPECT_NEAR(eye.z, 0.0f, 1e-5f);
    const glm::mat4 view = camera.view();
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(view[c][r]));
}

// A segment of length s through the target, across the line of sight, spans s / (2 d tan(fov/2)) of
// the image's height at distance d: s * H / (2 d tan(fov/2)) pixels, whatever the azimuth.
TEST(Camera, ScreenViewMeasuresPixelsOnTheImagePlane) {
    render::OrbitCamera camera;
    camera.target = glm::vec3(1.0f, 2.0f, -3.0f);
    camera.distance = 8.0f;
    camera.elevation_deg = 0.0f;
    camera.fov_y_deg = 40.0f;
    const glm::ivec2 size(800, 600);
    const double expected = 0.5 * 600.0 / (2.0 * 8.0 * std::tan(glm::radians(20.0)));  // for s = 0.5
    for (float azimuth : {0.0f, 90.0f, 215.0f}) {
        camera.azimuth_deg = azimuth;
        const rgb::ScreenView view = render::screen_view(camera, size);
        EXPECT_EQ(view.viewport, glm::dvec2(800.0, 600.0));
        EXPECT_NEAR(glm::distance(view.eye, glm::dvec3(camera.eye())), 0.0, 1e-6);
        // Vertical through the target (always across the line of sight at elevation 0).
        const glm::dvec3 t(camera.target);
        const glm::dvec4 p = view.view_projection * glm::dvec4(t + glm::dvec3(0.0, 0.25, 0.0), 1.0);
        const glm::dvec4 q = view.view_projection * glm::dvec4(t - glm::dvec3(0.0, 0.25, 0.0), 1.0);
        const glm::dvec2 pixels = 0.5 * (glm::dvec2(p) / p.w - glm::dvec2(q) / q.w) * view.viewport;
        EXPECT_NEAR(std::abs(pixels.x), 0.0, 1e-3) << azimuth;
        EXPECT_NEAR(std::abs(pixels.y), expected, 1e-3 * expected) << azimuth;
    }
}

}  // namespace
