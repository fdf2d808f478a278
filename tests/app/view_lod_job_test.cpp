// The editor's view-dependent mode as a job (app/view_lod_job.h): it follows the camera it is given
// each frame, settles for a still camera, and freezing it keeps the mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "app/view_lod_job.h"
#include "rgb/mesh/base_mesh.h"
#include "rgb/mesh/invariants.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/observer.h"
#include "rgb/mesh/surface_point.h"
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

// The vertices the job adds and removes, in order: each one's level, whether it plainly lies in view
// or out of it (judged here from the base mesh and the camera alone), and for a split the length on
// screen of the edge it split.
struct VertexEvent {
    bool added = true;
    int level = 0;
    bool in_view = false, out_of_view = false;
    bool facing_the_eye = false;  // in the picture, on a base face turned towards the eye at all
    double pixels = 0.0;
};

class VertexEvents : public rgb::MeshObserver {
public:
    VertexEvents(rgb::Mesh& mesh, const rgb::ScreenView& view) : mesh_(mesh), view_(view) { mesh_.add_observer(this); }
    ~VertexEvents() override { mesh_.remove_observer(this); }
    VertexEvents(const VertexEvents&) = delete;
    VertexEvents& operator=(const VertexEvents&) = delete;
    void vertex_added(const rgb::Mesh& mesh, rgb::VertexId v, rgb::VertexId a, rgb::VertexId b) override {
        VertexEvent e = classified(mesh, v);
        e.pixels = glm::length(0.5 * (screen(mesh.base_space_position(a)) - screen(mesh.base_space_position(b))) * view_.viewport);
        events.push_back(e);
    }
    void vertex_removed(const rgb::Mesh& mesh, rgb::VertexId v) override {
        VertexEvent e = classified(mesh, v);
        e.added = false;
        events.push_back(e);
    }
    std::vector<VertexEvent> events;

private:
    glm::dvec2 screen(const glm::dvec3& p) const {
        const glm::dvec4 clip = view_.view_projection * glm::dvec4(p, 1.0);
        return glm::dvec2(clip) / clip.w;
    }
    // A vertex inside its base face (not on a base edge) is in view when that face plainly faces the
    // eye and the vertex is well inside the picture, out of view when the face plainly faces away.
    VertexEvent classified(const rgb::Mesh& mesh, rgb::VertexId v) const {
        VertexEvent e;
        e.level = mesh.level(v);
        const rgb::SurfacePoint at = mesh.address(v);
        if (at.a[0] == 0 || at.a[1] == 0 || at.a[2] == 0) return e;
        const rgb::Triangle& t = mesh.base().face(at.face);
        const glm::dvec3 p0 = mesh.base().position(t[0]), p1 = mesh.base().position(t[1]), p2 = mesh.base().position(t[2]);
        const double facing = glm::dot(glm::normalize(glm::cross(p1 - p0, p2 - p0)), glm::normalize(view_.eye - (p0 + p1 + p2) / 3.0));
        const glm::dvec2 s = screen(mesh.base_space_position(v));
        e.facing_the_eye = facing > 0.0 && std::abs(s.x) < 0.9 && std::abs(s.y) < 0.9;
        e.in_view = facing > 0.5 && e.facing_the_eye;
        e.out_of_view = facing < -0.5;
        return e;
    }
    rgb::Mesh& mesh_;
    const rgb::ScreenView& view_;
};

// The first view, from the base mesh: coarse to fine, and within a level the longest edges on
// screen first.
TEST(ViewLodJob, RefinesWhatIsInViewCoarseToFineLargestFirst) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::icosahedron());
    const rgb::ScreenView view = camera_at({0.0, 0.0, 3.2});
    VertexEvents record(mesh, view);
    app::ViewLodJob job(mesh, {8.0, 1'000'000, rgb::kMaxLevel}, [&] { return view; });
    settle(job);
    std::vector<VertexEvent> seen;
    for (const VertexEvent& e : record.events)
        if (e.added && e.in_view) seen.push_back(e);
    ASSERT_GT(seen.size(), 1000u);
    // Coarse to fine: no split in view of level L after the first of level L + 2, and hardly any
    // after the first of level L + 1 (a split the conformity of a finer one needs, made on demand).
    std::vector<std::size_t> first(rgb::kMaxLevel + 2, seen.size()), late(rgb::kMaxLevel + 2, 0), count(rgb::kMaxLevel + 2, 0);
    for (std::size_t i = 0; i < seen.size(); ++i) first[static_cast<std::size_t>(seen[i].level)] = std::min(first[static_cast<std::size_t>(seen[i].level)], i);
    for (std::size_t i = 0; i < seen.size(); ++i) {
        const auto level = static_cast<std::size_t>(seen[i].level);
        ++count[level];
        EXPECT_LT(i, first[level + 2]) << "a level-" << level << " split after the first of level " << level + 2;
        if (i > first[level + 1]) ++late[level];
    }
    for (std::size_t level = 1; level <= rgb::kMaxLevel; ++level)
        EXPECT_LE(late[level] * 50, count[level]) << late[level] << " of " << count[level] << " level-" << level << " splits after the first of the next level";
    // Largest first: among the splits of one level (up to 4) on faces turned towards the eye, edges
    // foreshortened towards the silhouette or farther away come later: of two whose edges differ on
    // screen by more than half, the longer is split first.
    std::vector<VertexEvent> facing;
    for (const VertexEvent& e : record.events)
        if (e.added && e.facing_the_eye && e.level <= 4) facing.push_back(e);
    std::size_t ordered = 0, pairs = 0;
    for (std::size_t i = 0; i < facing.size(); ++i)
        for (std::size_t j = i + 1; j < facing.size(); ++j)
            if (facing[j].level == facing[i].level && std::max(facing[i].pixels, facing[j].pixels) > 1.5 * std::min(facing[i].pixels, facing[j].pixels)) {
                ++pairs;
                ordered += facing[i].pixels > facing[j].pixels;
            }
    ASSERT_GT(pairs, 100u);
    EXPECT_GE(ordered * 100, pairs * 90) << ordered << " of " << pairs << " pairs in order of size";
}

// A camera moved to the other side: what comes into view is refined before what left it is
// coarsened.
TEST(ViewLodJob, RefinesWhatComesIntoViewBeforeCoarseningWhatLeftIt) {
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(rgbtest::icosahedron());
    rgb::ScreenView view = camera_at({0.0, 0.0, 5.0});
    app::ViewLodJob job(mesh, {8.0, 1'000'000, rgb::kMaxLevel}, [&] { return view; });
    settle(job);
    view = camera_at({0.0, 0.0, -5.0});
    VertexEvents record(mesh, view);
    settle(job);
    std::size_t last_split = 0, splits = 0, removals = 0;
    for (std::size_t i = 0; i < record.events.size(); ++i)
        if (record.events[i].added && record.events[i].in_view) last_split = i, ++splits;
    std::size_t early_removals = 0;  // of vertices out of view, before the last split in view
    for (std::size_t i = 0; i < record.events.size(); ++i)
        if (!record.events[i].added && record.events[i].out_of_view) ++removals, early_removals += i < last_split;
    ASSERT_GT(splits, 500u);
    ASSERT_GT(removals, 500u);
    // Removing a vertex in view (where the surface turns edge-on, its edges get short on screen) can
    // need vertices next to it removed first, some of them out of view: hardly any.
    EXPECT_LE(early_removals * 50, removals) << early_removals << " of " << removals << " removals out of view came before the last split in view";
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
