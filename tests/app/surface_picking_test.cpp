// Ray picking and the brush footprint, against a second, independent distance computation.
#include <algorithm>
#include <array>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "app/surface_picking.h"
#include "render/surface_geometry.h"
#include "rgb/mesh.h"
#include "rgb/refine.h"
#include "small_meshes.h"

namespace app {
namespace {

using test::tetrahedron;

TEST(SurfacePicking, HitsTheFrontFaceAndSkipsBackFaces) {
    rgb::Mesh mesh = tetrahedron();
    render::SurfaceGeometry geometry;
    geometry.rebuild(mesh);
    // From far along +x+y+z, the slanted face {1,2,3} is the front one; its centroid is (1/3,1/3,1/3).
    const glm::dvec3 centroid(1.0 / 3.0);
    const Ray ray{glm::dvec3(3.0), glm::normalize(centroid - glm::dvec3(3.0))};
    const std::optional<SurfaceHit> hit = pick_surface(geometry, ray);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(mesh.face_vertices(hit->face)[0].idx + mesh.face_vertices(hit->face)[1].idx +
                  mesh.face_vertices(hit->face)[2].idx,
              6u);  // vertices 1, 2, 3
    EXPECT_NEAR(glm::distance(hit->point, centroid), 0.0, 1e-6);
    // The same line from inside looking out meets only back faces.
    const Ray inside{glm::dvec3(0.1), glm::normalize(glm::dvec3(1.0))};
    EXPECT_FALSE(pick_surface(geometry, inside).has_value());
}

// Distance from p to the segment [a, b].
double distance_to_segment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a;
    const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
    return glm::distance(p, a + t * ab);
}

// Distance from p to a triangle, computed differently from the app's Voronoi-region walk: the
// projection onto the plane if it falls inside (all barycentric coordinates >= 0), otherwise the
// nearest of the three edges.
double reference_distance(const glm::dvec3& p, const std::array<glm::dvec3, 3>& t) {
    const glm::dvec3 n = glm::normalize(glm::cross(t[1] - t[0], t[2] - t[0]));
    const glm::dvec3 q = p - glm::dot(p - t[0], n) * n;
    bool inside = true;
    for (int i = 0; i < 3; ++i) inside = inside && glm::dot(glm::cross(t[(i + 1) % 3] - t[i], q - t[i]), n) >= 0.0;
    if (inside) return glm::distance(p, q);
    return std::min({distance_to_segment(p, t[0], t[1]), distance_to_segment(p, t[1], t[2]), distance_to_segment(p, t[2], t[0])});
}

std::array<glm::dvec3, 3> corners(const render::SurfaceGeometry& geometry, rgb::FaceId f) {
    const auto v = geometry.vertices();
    return {glm::dvec3(v[3 * f.idx].position), glm::dvec3(v[3 * f.idx + 1].position), glm::dvec3(v[3 * f.idx + 2].position)};
}

// Faces clearly inside (distance below radius - margin) must be in the footprint, faces clearly
// outside must not; the few within the margin of the rim may go either way (rounding of two
// different computations).
void expect_footprint_is_the_sphere(const rgb::Mesh& mesh, const render::SurfaceGeometry& geometry,
                                    const std::vector<rgb::FaceId>& footprint, const glm::dvec3& centre, double radius,
                                    const std::vector<rgb::FaceId>& candidates) {
    constexpr double kMargin = 1e-9;
    std::vector<std::uint32_t> got;
    for (rgb::FaceId f : footprint) got.push_back(f.idx);
    std::sort(got.begin(), got.end());
    ASSERT_EQ(std::adjacent_find(got.begin(), got.end()), got.end()) << "a face listed twice";
    for (rgb::FaceId f : candidates) {
        ASSERT_TRUE(mesh.is_live(f));
        const double d = reference_distance(centre, corners(geometry, f));
        const bool listed = std::binary_search(got.begin(), got.end(), f.idx);
        if (d < radius - kMargin) {
            EXPECT_TRUE(listed) << "face " << f.idx << " at distance " << d << " is missing";
        } else if (d > radius + kMargin) {
            EXPECT_FALSE(listed) << "face " << f.idx << " at distance " << d << " is beyond the radius " << radius;
        }
    }
}

TEST(SurfacePicking, FootprintIsEveryFaceWithinTheSphereAroundTheHit) {
    rgb::Mesh mesh = tetrahedron();
    rgb::refine_uniform(mesh, 3);
    render::SurfaceGeometry geometry;
    geometry.rebuild(mesh);
    const Ray ray{glm::dvec3(3.0), glm::normalize(glm::dvec3(1.0 / 3.0) - glm::dvec3(3.0))};
    const SurfaceHit hit = *pick_surface(geometry, ray);
    const double radius = 0.1;
    const std::vector<rgb::FaceId> footprint = faces_in_sphere(mesh, geometry, hit.face, hit.point, radius);
    ASSERT_FALSE(footprint.empty());
    EXPECT_EQ(footprint.front(), hit.face) << "the seed comes first";
    // The sphere is small against the smooth middle of one face, so all it meets is one patch.
    std::vector<rgb::FaceId> all;
    for (rgb::FaceId f : mesh.faces()) all.push_back(f);
    expect_footprint_is_the_sphere(mesh, geometry, footprint, hit.point, radius, all);
    EXPECT_GT(footprint.size(), 1u);
    EXPECT_LT(footprint.size(), mesh.num_faces());
}

// A sheet lying 0.05 under the painted one is within the brush's sphere but not connected to the
// hit: the footprint stays on the sheet the brush touches.
TEST(SurfacePicking, FootprintDoesNotJumpToASheetUnderneath) {
    const int n = 20;
    const rgb::Mesh mesh = test::stacked_sheets(n, 0.05);
    render::SurfaceGeometry geometry;
    geometry.rebuild(mesh);
    const Ray down{glm::dvec3(0.013, 3.0, 0.021), glm::dvec3(0.0, -1.0, 0.0)};
    const std::optional<SurfaceHit> hit = pick_surface(geometry, down);
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->point.y, 0.05, 1e-6) << "the upper sheet is hit first (positions are floats)";
    const double radius = 0.2;
    const std::vector<rgb::FaceId> footprint = faces_in_sphere(mesh, geometry, hit->face, hit->point, radius);
    // The upper sheet's faces come after the lower sheet's 2 n^2.
    std::vector<rgb::FaceId> upper, lower;
    for (rgb::FaceId f : mesh.faces()) (f.idx < 2u * n * n ? lower : upper).push_back(f);
    ASSERT_EQ(upper.size(), 2u * n * n);
    expect_footprint_is_the_sphere(mesh, geometry, footprint, hit->point, radius, upper);
    for (rgb::FaceId f : footprint) EXPECT_GE(f.idx, 2u * n * n) << "face " << f.idx << " lies on the lower sheet";
    // The lower sheet does come within the radius: only connectivity keeps it out.
    std::size_t lower_within = 0;
    for (rgb::FaceId f : lower) lower_within += reference_distance(hit->point, corners(geometry, f)) < radius;
    EXPECT_GT(lower_within, 4u);
}

}  // namespace
}  // namespace app
