// The editor's view-dependent mode as a job (app/view_lod_job.h): it follows the camera it is given
// each frame, settles for a still camera, and freezing it keeps the mesh.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "app/view_lod_job.h"
#include "rgb/mesh/invariants.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/loop_geometry.h"
#include "support/same_mesh.h"
#include "support/test_meshes.h"

namespace {

constexpr double kPixels = 12.0;
constexpr glm::dvec2 kScreen{640.0, 480.0};

rgb::ScreenView camera_at(const glm::dvec3& eye) {
    rgb::ScreenView view;
    view.viewport = kScreen;
    view.eye = eye;
    view.view_projection = glm::perspective(glm::radians(40.0), kScreen.x / kScreen.y, 0.01, 100.0) *
                           glm::lookAt(eye, glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0));
    return view;
}

// Steps like the editor's frames (each takes the camera as it is then) until the job reports the
// mesh settled.
void settle(app::ViewLodJob& job) {
    for (int frame = 0; frame < 100000; ++frame) {
        EXPECT_TRUE(job.step(std::chrono::milliseconds(5)));
        if (job.converged()) return;
    }
    ADD_FAILURE() << "the job did not settle";
}

// The longest green edge, in pixels, among those of faces that plainly face the eye and lie well
// inside the picture: measured here from the edge's ends in the uniform mesh of its level and the
// camera's matrix, apart from the criterion the updater uses.
double longest_visible_edge(const rgb::Mesh& mesh, const rgb::ScreenView& view) {
    double longest = 0.0;
    for (rgb::FaceId f : mesh.faces()) {
        const auto corners = mesh.face_vertices(f);
        glm::dvec3 p[3];
        for (int i = 0; i < 3; ++i) p[i] = rgb::displayed_position(mesh, corners[static_cast<std::size_t>(i)]);
        const glm::dvec3 normal = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
        const glm::dvec3 to_eye = glm::normalize(view.eye - (p[0] + p[1] + p[2]) / 3.0);
        if (glm::dot(normal, to_eye) < 0.7) continue;
        for (int i = 0; i < 3; ++i) {
            const rgb::HalfedgeId h = rgb::Mesh::halfedge(f, i);
            const rgb::EdgeType type = mesh.edge_type(h);
            if (type.colour != rgb::Colour::Green) continue;
            glm::dvec2 ends[2];
            bool inside = true;
            for (int e = 0; e < 2; ++e) {
                const rgb::VertexId v = e == 0 ? mesh.from_vertex(h) : mesh.to_vertex(h);
                const glm::dvec4 clip = view.view_projection * glm::dvec4(rgb::control_point(mesh, v, type.level), 1.0);
                ends[e] = glm::dvec2(clip) / clip.w;
                inside = inside && clip.w > 0.0 && std::abs(ends[e].x) < 0.8 && std::abs(ends[e].y) < 0.8;
            }
            if (inside) longest = std::max(longest, glm::length(0.5 * (ends[0] - ends[1]) * kScreen));
        }
    }
    return longest;
}

// Faces of level >= 3 whose centre (in base space) lies on the +z or the -z side.
std::pair<int, int> fine_faces_front_and_back(const rgb::Mesh& mesh) {
    int front = 0, back = 0;
    for (rgb::FaceId f : mesh.faces()) {
        if (mesh.level(f) < 3) continue;
        double z = 0.0;
        for (rgb::VertexId v : mesh.face_vertices(f)) z += mesh.base_space_position(v).z;
        (z > 0.0 ? front : back) += 1;
    }
    return {front, back};
}

TEST(ViewLodJob, SettlesForAStillCameraAndThenLeavesTheMeshAlone) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::icosahedron());
    const rgb::ScreenView view = camera_at({0.0, 0.0, 2.2});
    app::ViewLodJob job(mesh, {kPixels, 1'000'000, rgb::kMaxLevel}, [&] { return view; });
    EXPECT_EQ(job.progress(), 0.0f);
    settle(job);
    EXPECT_EQ(job.progress(), 1.0f);
    EXPECT_TRUE(job.changed());
    EXPECT_GT(mesh.num_faces(), 20u * 16u);  // some of it is at level 3 or finer
    EXPECT_LE(longest_visible_edge(mesh, view), kPixels);
    EXPECT_TRUE(rgb::check_invariants(mesh).ok());
    const rgb::Mesh settled = mesh;
    for (int frame = 0; frame < 5; ++frame) EXPECT_TRUE(job.step(std::chrono::milliseconds(5)));
    EXPECT_TRUE(rgbtest::same_mesh(settled, mesh));
}

TEST(ViewLodJob, DetailFollowsTheCameraToTheOtherSide) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::icosahedron());
    rgb::ScreenView view = camera_at({0.0, 0.0, 1.8});
    app::ViewLodJob job(mesh, {kPixels, 1'000'000, rgb::kMaxLevel}, [&] { return view; });
    settle(job);
    const auto [front_before, back_before] = fine_faces_front_and_back(mesh);
    EXPECT_GT(front_before, 0);
    EXPECT_EQ(back_before, 0);
    view = camera_at({0.0, 0.0, -1.8});  // the job asks for the camera every frame
    settle(job);
    const auto [front_after, back_after] = fine_faces_front_and_back(mesh);
    EXPECT_EQ(front_after, 0);
    EXPECT_GT(back_after, 0);
    EXPECT_LE(longest_visible_edge(mesh, view), kPixels);
    EXPECT_GT(job.stats().removals, 0u);
}

TEST(ViewLodJob, FreezingKeepsTheMeshAsItIs) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::icosahedron());
    rgb::ScreenView view = camera_at({0.0, 0.0, 2.2});
    app::ViewLodJob job(mesh, {kPixels, 1'000'000, rgb::kMaxLevel}, [&] { return view; });
    settle(job);
    const rgb::Mesh frozen = mesh;
    job.cancel();
    view = camera_at({0.0, 0.0, -2.2});
    EXPECT_FALSE(job.step(std::chrono::milliseconds(5)));
    EXPECT_TRUE(rgbtest::same_mesh(frozen, mesh));
    EXPECT_FALSE(job.script().has_value());
}

}  // namespace
