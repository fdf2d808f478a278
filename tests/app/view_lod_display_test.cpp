// What the editor shows while view-dependent LOD follows an orbiting camera: at every frame the
// displayed triangles (what the renderer uploads) form one whole, closed, conforming and consistently
// oriented mesh, however much work each frame does.
#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cstdint>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "app/editor.h"
#include "editor_fixture.h"
#include "render/surface_geometry.h"
#include "support/test_meshes.h"

namespace app {
namespace {

using test::kViewport;

// Why the live triangles of `shown` are not a closed oriented surface of genus 0 facing outwards,
// or "" when they are. Corners are the same vertex when their positions have the same bits (the
// geometry writes every corner of a vertex from one position). A hole or a T-junction leaves a
// directed edge without its reverse; a duplicated or inverted face repeats a directed edge.
std::string whole_surface_problem(const render::SurfaceGeometry& shown) {
    using Bits = std::array<std::uint32_t, 3>;
    const auto corners = shown.vertices();
    std::vector<Bits> triangles_bits;  // three corners a live slot
    for (std::size_t slot = 0; slot < shown.face_slots(); ++slot) {
        if ((corners[3 * slot].code & render::kCodeLiveBit) == 0) continue;
        for (std::size_t i = 0; i < 3; ++i) triangles_bits.push_back(std::bit_cast<Bits>(corners[3 * slot + i].position));
    }
    std::vector<Bits> points = triangles_bits;
    std::ranges::sort(points);
    points.erase(std::unique(points.begin(), points.end()), points.end());
    const auto id = [&](const Bits& b) { return static_cast<int>(std::ranges::lower_bound(points, b) - points.begin()); };
    const auto position = [&](int v) { return glm::dvec3(std::bit_cast<glm::vec3>(points[static_cast<std::size_t>(v)])); };
    std::vector<std::pair<int, int>> directed;
    double volume6 = 0.0;  // six times the enclosed volume, positive for outward faces
    const std::size_t triangles = triangles_bits.size() / 3;
    for (std::size_t t = 0; t < triangles; ++t) {
        const int v[3] = {id(triangles_bits[3 * t]), id(triangles_bits[3 * t + 1]), id(triangles_bits[3 * t + 2])};
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) return "a degenerate triangle";
        for (int i = 0; i < 3; ++i) directed.emplace_back(v[i], v[(i + 1) % 3]);
        volume6 += glm::dot(position(v[0]), glm::cross(position(v[1]), position(v[2])));
    }
    std::ranges::sort(directed);
    std::size_t open = 0, repeated = 0;
    for (std::size_t i = 0; i < directed.size(); ++i) {
        if (i > 0 && directed[i] == directed[i - 1]) ++repeated;
        if (!std::ranges::binary_search(directed, std::pair{directed[i].second, directed[i].first})) ++open;
    }
    std::ostringstream problem;
    if (open > 0) problem << open << " edges without a neighbour (holes or T-junctions); ";
    if (repeated > 0) problem << repeated << " edges repeated in one direction (duplicated or inverted faces); ";
    const long long euler = static_cast<long long>(points.size()) - static_cast<long long>(directed.size() / 2) +
                            static_cast<long long>(triangles);
    if (open == 0 && repeated == 0 && euler != 2) problem << "Euler characteristic " << euler << ", not a sphere's 2; ";
    if (volume6 <= 0.0) problem << "faces turned inwards; ";
    return problem.str();
}

class ViewLodDisplay : public ::testing::Test {
protected:
    void SetUp() override {
        editor.document().adopt(rgbtest::make_rgb_mesh(rgbtest::icosahedron()), "");
        editor.reset_view();
        ASSERT_EQ(whole_surface_problem(editor.document().shown()), "");
    }

    // Orbits by `frames` right-drag moves of `step` pixels, one frame of `slice` each, as the window
    // draws them; checks the displayed triangles after every frame, returns how many frames showed
    // a mesh other than the one the frame ended with.
    void orbit(int frames, glm::vec2 step, std::chrono::microseconds slice) {
        glm::vec2 at{0.5f * kViewport.x, 0.5f * kViewport.y};
        editor.mouse_moved(at);
        editor.mouse_pressed(MouseButton::Right, {});
        for (int frame = 0; frame < frames; ++frame) {
            at += step;
            editor.mouse_moved(at);
            editor.update(slice);
            editor.document().take_display_changes();
            const std::string problem = whole_surface_problem(editor.document().shown());
            ASSERT_EQ(problem, "") << "frame " << frame << " of the orbit, " << editor.document().mesh().num_faces()
                                   << " triangles in the mesh";
        }
        editor.mouse_released(MouseButton::Right);
    }

    Editor editor{kViewport};
};

// Frames of the usual 60 Hz slice: each one's work is small.
TEST_F(ViewLodDisplay, EveryFrameOfAnOrbitShowsAWholeMesh) {
    editor.detail_settings().view_pixels = 10.0;
    editor.start_view_lod();
    orbit(16, {16.0f, 4.0f}, std::chrono::milliseconds(10));
    EXPECT_GT(editor.document().mesh().num_faces(), 20u * 16u) << "the orbit refined what it saw";
}

// Slow frames (a software renderer drawing millions of triangles gives the work hundreds of
// milliseconds a frame, job_pacer.h): far more work a frame than the display catches up in one part.
TEST_F(ViewLodDisplay, SlowFramesShowAWholeMeshToo) {
    editor.detail_settings().view_pixels = 3.0;
    editor.start_view_lod();
    orbit(20, {20.0f, 0.0f}, std::chrono::milliseconds(200));
    EXPECT_GT(editor.document().mesh().num_faces(), kDisplayPartFaces) << "the frames did more than one part of the catching up takes";
}

}  // namespace
}  // namespace app
