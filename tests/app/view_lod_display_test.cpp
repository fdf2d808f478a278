// What the editor shows while view-dependent LOD follows an orbiting camera: at every frame the
// displayed triangles (what the renderer uploads) form one whole, closed, conforming and consistently
// oriented mesh, however much work each frame does.
#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdint>
#include <sstream>
#include <string>
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

// A corner's position, as bits: corners are the same vertex when their positions have the same bits
// (the geometry writes every corner of a vertex from one position).
struct PositionBits {
    std::uint32_t x, y, z;
    bool operator==(const PositionBits&) const = default;
};
struct CornerBits {
    PositionBits bits;
    std::uint32_t corner;  // its place among the live triangles' corners
};

// Orders corners by their bits. Written out, as is the directed edges' packing below: the test
// files build at -O0 under the sanitizers, where std::ranges' comparisons of arrays and pairs (a
// dozen calls each) made these checks four fifths of the slow-frames test there.
bool bits_before(const CornerBits& a, const CornerBits& b) {
    if (a.bits.x != b.bits.x) return a.bits.x < b.bits.x;
    if (a.bits.y != b.bits.y) return a.bits.y < b.bits.y;
    return a.bits.z < b.bits.z;
}

// The directed edge from vertex `from` to vertex `to`, as one integer.
std::uint64_t directed_edge(std::uint32_t from, std::uint32_t to) { return std::uint64_t{from} << 32 | to; }

// Why the live triangles of `shown` are not a closed oriented surface of genus 0 facing outwards,
// or "" when they are. A hole or a T-junction leaves a directed edge without its reverse; a
// duplicated or inverted face repeats a directed edge.
std::string whole_surface_problem(const render::SurfaceGeometry& shown) {
    const auto corners = shown.vertices();
    std::vector<CornerBits> live_corners;  // three corners a live slot
    for (std::size_t slot = 0; slot < shown.face_slots(); ++slot) {
        if ((corners[3 * slot].code & render::kCodeLiveBit) == 0) continue;
        for (std::size_t i = 0; i < 3; ++i) {
            const auto corner = static_cast<std::uint32_t>(live_corners.size());
            live_corners.push_back({std::bit_cast<PositionBits>(corners[3 * slot + i].position), corner});
        }
    }
    const std::size_t triangles = live_corners.size() / 3;
    // Each corner's vertex: vertices numbered in the order of their bits.
    std::vector<std::uint32_t> vertex_of(live_corners.size());
    std::vector<glm::dvec3> positions;
    std::sort(live_corners.begin(), live_corners.end(), bits_before);
    for (std::size_t i = 0; i < live_corners.size(); ++i) {
        const CornerBits& c = live_corners[i];
        if (i == 0 || c.bits != live_corners[i - 1].bits) positions.emplace_back(std::bit_cast<glm::vec3>(c.bits));
        vertex_of[c.corner] = static_cast<std::uint32_t>(positions.size() - 1);
    }
    std::vector<std::uint64_t> directed;
    double volume6 = 0.0;  // six times the enclosed volume, positive for outward faces
    for (std::size_t t = 0; t < triangles; ++t) {
        const std::uint32_t v[3] = {vertex_of[3 * t], vertex_of[3 * t + 1], vertex_of[3 * t + 2]};
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) return "a degenerate triangle";
        for (int i = 0; i < 3; ++i) directed.push_back(directed_edge(v[i], v[(i + 1) % 3]));
        volume6 += glm::dot(positions[v[0]], glm::cross(positions[v[1]], positions[v[2]]));
    }
    std::sort(directed.begin(), directed.end());
    std::size_t open = 0, repeated = 0;
    for (std::size_t i = 0; i < directed.size(); ++i) {
        if (i > 0 && directed[i] == directed[i - 1]) ++repeated;
        const auto from = static_cast<std::uint32_t>(directed[i] >> 32), to = static_cast<std::uint32_t>(directed[i]);
        if (!std::binary_search(directed.begin(), directed.end(), directed_edge(to, from))) ++open;
    }
    std::ostringstream problem;
    if (open > 0) problem << open << " edges without a neighbour (holes or T-junctions); ";
    if (repeated > 0) problem << repeated << " edges repeated in one direction (duplicated or inverted faces); ";
    const long long euler = static_cast<long long>(positions.size()) - static_cast<long long>(directed.size() / 2) +
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
