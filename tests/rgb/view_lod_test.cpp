// View-dependent continuous LOD (rgb/lod/view_lod.h) and the screen criterion (rgb/lod/screen_detail.h):
// updates converge, and then no edge on screen is longer than the threshold, nothing removable is
// shorter than half of it (so nothing outside the view or turned away stays but what visible detail
// needs), a still camera changes nothing, and the mesh holds the canonical screen-space request's
// result; the same holds along an orbit.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>
#include <tuple>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "rgb/lod/lod_criteria.h"
#include "rgb/lod/requests.h"
#include "rgb/lod/screen_detail.h"
#include "rgb/lod/view_lod.h"
#include "rgb/mesh/invariants.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/operators.h"
#include "support/same_mesh.h"
#include "support/test_meshes.h"

namespace rgbtest {
namespace {

constexpr double kPixels = 12.0;

// A camera at `eye` looking at the origin, 640x480 pixels.
rgb::ScreenView camera(const glm::dvec3& eye, double fov_deg = 40.0) {
    rgb::ScreenView view;
    view.viewport = {640.0, 480.0};
    view.eye = eye;
    view.view_projection = glm::perspective(glm::radians(fov_deg), 640.0 / 480.0, 0.01, 100.0) *
                           glm::lookAt(eye, glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0));
    return view;
}

void converge(rgb::ViewLod& lod) {
    for (int i = 0; i < 100000 && !lod.update(std::chrono::milliseconds(50)); ++i) {
    }
    ASSERT_TRUE(lod.converged());
}

using Point = std::tuple<double, double, double>;
std::set<Point> base_space_points(const rgb::Mesh& mesh) {
    std::set<Point> s;
    for (rgb::VertexId v : mesh.vertices()) {
        const glm::dvec3 p = mesh.base_space_position(v);
        s.insert({p.x, p.y, p.z});
    }
    return s;
}

// What a converged mesh promises for the view.
void expect_settled(const rgb::Mesh& mesh, const rgb::ViewLod& lod) {
    std::size_t kept_for_others = 0;
    for (rgb::FaceId f : mesh.faces())
        for (int i = 0; i < 3; ++i) {
            const rgb::HalfedgeId h = rgb::Mesh::halfedge(f, i);
            if (mesh.edge_type(h).colour != rgb::Colour::Green) continue;
            EXPECT_LE(lod.edge_value(h), kPixels);
        }
    for (rgb::VertexId v : mesh.vertices()) {
        if (mesh.level(v) == 0) continue;
        if (!rgb::can_remove_vertex(mesh, v)) {
            ++kept_for_others;
            continue;
        }
        const std::optional<double> value = lod.parent_value(v);
        ASSERT_TRUE(value.has_value());
        EXPECT_GE(*value, 0.5 * kPixels);
    }
    EXPECT_TRUE(rgb::check_invariants(mesh).ok());
    EXPECT_TRUE(rgb::check_normal_form(mesh).ok());
}

// The canonical request for the same view: every vertex it holds is in the converged mesh.
void expect_holds_the_request(const rgb::Mesh& mesh, const TestMesh& base, const rgb::ScreenView& view) {
    rgb::Mesh request = make_rgb_mesh(base);
    rgb::DetailRequest r;
    r.value = rgb::ScreenCriterion(request.shared_base(), view).edge_value();
    r.threshold = kPixels;
    rgb::apply_detail_request(request, r);
    const std::set<Point> wanted = base_space_points(request), held = base_space_points(mesh);
    EXPECT_TRUE(std::includes(held.begin(), held.end(), wanted.begin(), wanted.end()));
    EXPECT_GT(request.num_faces(), base.triangles.size());
}

TEST(ViewLod, ConvergesAndAStillCameraChangesNothing) {
    const TestMesh base = icosahedron();
    rgb::Mesh mesh = make_rgb_mesh(base);
    const rgb::ScreenView view = camera({0.0, 0.3, 2.2});
    rgb::ViewLod lod(mesh, {kPixels, 1'000'000, rgb::kMaxLevel}, view);
    converge(lod);
    EXPECT_GT(lod.stats().splits, 0u);
    expect_settled(mesh, lod);
    expect_holds_the_request(mesh, base, view);
    const rgb::Mesh before = mesh;
    lod.set_view(view);
    EXPECT_TRUE(lod.update(std::chrono::seconds(10)));
    EXPECT_TRUE(same_mesh(before, mesh));
}

// Close to one side of the mesh: the far side and what lies outside the view stay coarse.
TEST(ViewLod, OutsideTheViewAndOnTheBackOnlyWhatVisibleDetailNeeds) {
    const TestMesh base = icosahedron();
    rgb::Mesh mesh = make_rgb_mesh(base);
    const rgb::ScreenView view = camera({0.0, 0.0, 1.6}, 25.0);
    rgb::ViewLod lod(mesh, {kPixels, 1'000'000, rgb::kMaxLevel}, view);
    converge(lod);
    expect_settled(mesh, lod);
    // The back (z < -0.5) holds only base vertices and what the front's splits need around them.
    int back_level = 0, front_level = 0;
    for (rgb::FaceId f : mesh.faces()) {
        double z = 0.0;
        for (rgb::VertexId v : mesh.face_vertices(f)) z += mesh.base_space_position(v).z / 3.0;
        (z < -0.5 ? back_level : front_level) = std::max(z < -0.5 ? back_level : front_level, mesh.level(f));
    }
    EXPECT_GE(front_level, 3);
    EXPECT_LE(back_level, 1);
}

TEST(ViewLod, FollowsAnOrbit) {
    const TestMesh base = bipyramid(7);
    rgb::Mesh mesh = make_rgb_mesh(base);
    rgb::ViewLod lod(mesh, {kPixels, 1'000'000, rgb::kMaxLevel}, camera({0.0, 0.5, 2.5}));
    for (int step = 0; step < 6; ++step) {
        const double angle = 0.6 * step;
        const rgb::ScreenView view = camera({2.5 * std::sin(angle), 0.5, 2.5 * std::cos(angle)});
        lod.set_view(view);
        converge(lod);
        SCOPED_TRACE("step " + std::to_string(step));
        expect_settled(mesh, lod);
        expect_holds_the_request(mesh, base, view);
    }
    EXPECT_GT(lod.stats().removals, 0u);
}

// While the camera moves the view changes before every slice; the sweep must still reach every face
// (not start over at the first one each time). One face slot per call (a zero budget), the camera
// jittering between two positions a hair apart, until a long run of calls changes nothing.
TEST(ViewLod, ASweepGoesOnAcrossCameraChanges) {
    rgb::Mesh mesh = make_rgb_mesh(icosahedron());
    const rgb::ScreenView views[2] = {camera({0.0, 0.3, 2.2}), camera({0.0, 0.3, 2.2 + 1e-12})};
    rgb::ViewLod lod(mesh, {kPixels, 1'000'000, rgb::kMaxLevel}, views[0]);
    std::size_t calls = 0, calls_since_change = 0, changes = 0;
    for (; calls < 2'000'000 && calls_since_change <= 2 * mesh.face_capacity(); ++calls) {
        lod.set_view(views[calls % 2]);
        lod.update(std::chrono::microseconds(0));
        const std::size_t now = lod.stats().splits + lod.stats().removals;
        calls_since_change = now == changes ? calls_since_change + 1 : 0;
        changes = now;
    }
    EXPECT_LT(calls, 2'000'000u);
    EXPECT_GT(mesh.num_faces(), 20u * 16u);
    expect_settled(mesh, lod);
}

TEST(ScreenDetail, TheRequestIgnoresStorageAndHistory) {
    const TestMesh base = bipyramid(7);
    const rgb::ScreenView view = camera({1.0, 0.8, 2.0});
    auto run = [&](const TestMesh& m, int start_level) {
        rgb::Mesh mesh = make_rgb_mesh(m);
        rgb::set_level(mesh, start_level);
        rgb::DetailRequest r;
        r.value = rgb::ScreenCriterion(mesh.shared_base(), view).edge_value();
        r.threshold = kPixels;
        rgb::apply_detail_request(mesh, r);
        return mesh;
    };
    const rgb::Mesh fresh = run(base, 0);
    EXPECT_GT(fresh.num_faces(), 4 * base.triangles.size());
    EXPECT_TRUE(same_mesh(fresh, run(base, 3)));
    for (const TestMesh& stored : {with_rotated_corners(base), with_reversed_faces(base), with_shuffled_vertices(base, 5)})
        EXPECT_TRUE(same_mesh(fresh, run(stored, 0))) << stored.name;
}

TEST(ViewLod, StaysWithinItsTriangleBudget) {
    rgb::Mesh mesh = make_rgb_mesh(icosahedron());
    rgb::ViewLod lod(mesh, {0.5, 3000, rgb::kMaxLevel}, camera({0.0, 0.3, 2.2}));
    converge(lod);
    EXPECT_LE(mesh.num_faces(), 3000u + 12u);  // the last split may bring a few dependencies along
    EXPECT_GT(mesh.num_faces(), 2500u);
}

}  // namespace
}  // namespace rgbtest
