// Ray picking on a known triangle, and what a dab may paint with its view test
// (rgb::facing_base_faces, the brush's footprint since dabs are requests in base space) against a
// second, independent computation: distances by plane projection or edges, facing by the plain
// cross product, connectivity through an edge map built here.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "app/surface_index.h"
#include "render/surface_geometry.h"
#include "rgb/lod/dab.h"
#include "rgb/lod/refine.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/loop_geometry.h"
#include "small_meshes.h"

namespace app {
namespace {

using test::tetrahedron;

TEST(SurfacePicking, HitsTheFrontFaceAndSkipsBackFaces) {
    rgb::Mesh mesh = tetrahedron();
    render::SurfaceGeometry geometry;
    geometry.rebuild(mesh);
    SurfaceIndex index;
    index.rebuild(mesh, geometry);
    // From far along +x+y+z, the slanted face {1,2,3} is the front one; its centroid is (1/3,1/3,1/3).
    const glm::dvec3 centroid(1.0 / 3.0);
    const Ray ray{glm::dvec3(3.0), glm::normalize(centroid - glm::dvec3(3.0))};
    const std::optional<SurfaceHit> hit = index.pick(geometry, ray);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(mesh.face_vertices(hit->face)[0].idx + mesh.face_vertices(hit->face)[1].idx +
                  mesh.face_vertices(hit->face)[2].idx,
              6u);  // vertices 1, 2, 3
    EXPECT_NEAR(glm::distance(hit->point, centroid), 0.0, 1e-6);
    // The same line from inside looking out meets only back faces.
    const Ray inside{glm::dvec3(0.1), glm::normalize(glm::dvec3(1.0))};
    EXPECT_FALSE(index.pick(geometry, inside).has_value());
}

// A plain triangle list: the base mesh a footprint is computed on.
struct Triangles {
    std::vector<glm::dvec3> positions;
    std::vector<rgb::Triangle> triangles;
    std::array<glm::dvec3, 3> corners(std::size_t f) const {
        return {positions[triangles[f][0]], positions[triangles[f][1]], positions[triangles[f][2]]};
    }
};

// The displayed surface of `mesh` as a triangle list, to serve as a finer base mesh.
Triangles displayed_triangles(const rgb::Mesh& mesh) {
    Triangles out;
    std::map<std::uint32_t, std::uint32_t> index;
    for (rgb::VertexId v : mesh.vertices()) {
        index[v.idx] = static_cast<std::uint32_t>(out.positions.size());
        out.positions.push_back(rgb::displayed_position(mesh, v));
    }
    for (rgb::FaceId f : mesh.faces()) {
        const auto& v = mesh.face_vertices(f);
        out.triangles.push_back({index[v[0].idx], index[v[1].idx], index[v[2].idx]});
    }
    return out;
}

// Distance from p to the segment [a, b].
double distance_to_segment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a;
    const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
    return glm::distance(p, a + t * ab);
}

// Distance from p to a triangle, computed differently from the core's Voronoi-region walk: the
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

// How much the unit normal of face f turns towards the viewer looking along `view` (> 0: facing).
double facing(const Triangles& mesh, std::size_t f, const glm::dvec3& view) {
    const auto c = mesh.corners(f);
    return -glm::dot(glm::normalize(glm::cross(c[1] - c[0], c[2] - c[0])), glm::normalize(view));
}

// The faces a dab at `centre` may paint: those within `radius` that face the viewer, connected
// through such faces (across shared edges) to the facing face nearest the centre. Rounding of two
// different computations may disagree only for faces right at the rim or seen edge-on, so the test
// asserts first that there are none.
std::vector<std::uint32_t> reference_footprint(const Triangles& mesh, const glm::dvec3& centre, double radius,
                                               const glm::dvec3& view) {
    constexpr double kMargin = 1e-9;
    const std::size_t n = mesh.triangles.size();
    std::vector<bool> eligible(n);
    std::size_t seed = n;
    double seed_distance = 0.0;
    for (std::size_t f = 0; f < n; ++f) {
        const double d = reference_distance(centre, mesh.corners(f)), turn = facing(mesh, f, view);
        EXPECT_GT(std::abs(d - radius), kMargin) << "face " << f << " lies on the rim";
        EXPECT_GT(std::abs(turn), kMargin) << "face " << f << " is seen edge-on";
        eligible[f] = d <= radius && turn > 0.0;
        if (eligible[f] && (seed == n || d < seed_distance)) seed = f, seed_distance = d;
    }
    std::vector<std::uint32_t> reached;
    if (seed == n) return reached;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> faces_of_edge;
    for (std::uint32_t f = 0; f < n; ++f)
        for (int i = 0; i < 3; ++i) {
            const std::uint32_t a = mesh.triangles[f][i], b = mesh.triangles[f][(i + 1) % 3];
            faces_of_edge[{std::min(a, b), std::max(a, b)}].push_back(f);
        }
    std::vector<bool> seen(n);
    std::vector<std::uint32_t> queue{static_cast<std::uint32_t>(seed)};
    seen[seed] = true;
    while (!queue.empty()) {
        const std::uint32_t f = queue.back();
        queue.pop_back();
        reached.push_back(f);
        for (int i = 0; i < 3; ++i) {
            const std::uint32_t a = mesh.triangles[f][i], b = mesh.triangles[f][(i + 1) % 3];
            for (std::uint32_t g : faces_of_edge[{std::min(a, b), std::max(a, b)}])
                if (eligible[g] && !seen[g]) {
                    seen[g] = true;
                    queue.push_back(g);
                }
        }
    }
    std::sort(reached.begin(), reached.end());
    return reached;
}

std::vector<std::uint32_t> footprint(const Triangles& mesh, const glm::dvec3& centre, double radius, const glm::dvec3& view) {
    return rgb::facing_base_faces(rgb::Mesh(mesh.positions, mesh.triangles), rgb::Sphere{centre, radius}, view);
}

// Level 3 of the tetrahedron as the base: a small ball on the smooth middle of the front face takes a
// patch of it; a larger one around the front of corner (1,0,0) meets the faces behind the corner too,
// which face away and stay out.
TEST(BrushFootprint, IsEveryFacingFaceWithinTheBallConnectedToTheHit) {
    rgb::Mesh refined = tetrahedron();
    rgb::refine_uniform(refined, 3);
    const Triangles mesh = displayed_triangles(refined);
    ASSERT_EQ(mesh.triangles.size(), 4u * 64u);
    const glm::dvec3 view = glm::normalize(glm::dvec3(-1.0));
    render::SurfaceGeometry geometry;
    geometry.rebuild(refined);
    SurfaceIndex index;
    index.rebuild(refined, geometry);
    const std::optional<SurfaceHit> hit = index.pick(geometry, Ray{glm::dvec3(3.0), view});
    ASSERT_TRUE(hit.has_value());

    const std::vector<std::uint32_t> patch = reference_footprint(mesh, hit->point, 0.1, view);
    EXPECT_GT(patch.size(), 1u);
    EXPECT_LT(patch.size(), mesh.triangles.size() / 4);
    EXPECT_EQ(footprint(mesh, hit->point, 0.1, view), patch);

    const glm::dvec3 corner = rgb::displayed_position(refined, rgb::VertexId(1));
    const glm::dvec3 near_corner = corner + 0.05 * glm::normalize(glm::dvec3(1.0));
    std::size_t within = 0;
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) within += reference_distance(near_corner, mesh.corners(f)) <= 0.3;
    const std::vector<std::uint32_t> front = reference_footprint(mesh, near_corner, 0.3, view);
    EXPECT_LT(front.size(), within) << "faces behind the corner are within the ball but face away";
    EXPECT_GT(front.size(), 2u);
    EXPECT_EQ(footprint(mesh, near_corner, 0.3, view), front);
}

// A sheet lying 0.05 under the painted one is within the dab's ball and faces the viewer too, but is
// not connected to the hit: the footprint stays on the sheet the brush touches.
TEST(BrushFootprint, DoesNotJumpToASheetUnderneath) {
    const int n = 20;
    const rgb::Mesh sheets = test::stacked_sheets(n, 0.05);
    const Triangles mesh = displayed_triangles(sheets);
    const glm::dvec3 down(0.0, -1.0, 0.0), centre(0.013, 0.05, 0.021);
    const double radius = 0.2;
    const std::vector<std::uint32_t> expected = reference_footprint(mesh, centre, radius, down);
    // The upper sheet's faces come after the lower sheet's 2 n^2.
    EXPECT_GT(expected.size(), 4u);
    for (std::uint32_t f : expected) EXPECT_GE(f, 2u * n * n) << "face " << f << " lies on the lower sheet";
    EXPECT_EQ(footprint(mesh, centre, radius, down), expected);
    // The lower sheet does come within the radius: only connectivity keeps it out.
    std::size_t lower_within = 0;
    for (std::uint32_t f = 0; f < 2u * n * n; ++f) lower_within += reference_distance(centre, mesh.corners(f)) < radius;
    EXPECT_GT(lower_within, 4u);
}

}  // namespace
}  // namespace app
