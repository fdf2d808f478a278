// A cage with detail through save and load (state format version 5, io/state/detail_state.h): the
// saved file resumes without the surface it was sampled from; every vertex of every level is where
// the detail puts it, bit for bit, after a reload, a refine of the reloaded file and a level 0; an
// edited v line or a changed detail value is caught; a malformed section is an error naming its line;
// other OBJ readers see the displayed mesh.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/mesh_file.h"
#include "io/obj/obj_error.h"
#include "io/obj_reader.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/detail_positions.h"
#include "rgb/values/loop_geometry.h"

namespace rgbio {
namespace {

constexpr int kDetailLevel = 2;

// An octahedron cage; its detail a sphere of radius 1.25 around it (each point pushed out radially
// from the base-space point), values that need 17 digits.
std::shared_ptr<const rgb::BaseMesh> cage_with_detail() {
    const std::vector<glm::dvec3> positions{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const std::vector<rgb::Triangle> triangles{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    const rgb::BaseMesh plain(positions, triangles);
    std::vector<glm::dvec3> values;
    for (const rgb::SurfacePoint& p : rgb::DetailPositions::grid_points(plain, kDetailLevel)) {
        const glm::dvec3 q = rgb::base_space_position(plain, p);
        values.push_back(1.25 * q / std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z));
    }
    auto detail = std::make_shared<const rgb::DetailPositions>(plain, kDetailLevel, values,
                                                               rgb::DetailOrigin{"scan with spaces.obj", 12345, 7});
    return std::make_shared<const rgb::BaseMesh>(positions, triangles, rgb::SharpFeatures{}, detail);
}

void expect_on_detail(const rgb::Mesh& mesh, const rgb::BaseMesh& reference) {
    ASSERT_NE(mesh.base().detail(), nullptr);
    for (rgb::VertexId v : mesh.vertices())
        ASSERT_EQ(rgb::displayed_position(mesh, v), reference.detail()->position(reference, mesh.address(v)));
}

TEST(DetailRoundTrip, ASavedCageResumesWithItsDetail) {
    const auto base = cage_with_detail();
    rgb::Mesh mesh(base);
    rgb::set_level(mesh, 3, rgb::Sphere{{1, 0, 0}, 0.8});
    const std::string text = format_obj(mesh, {});
    EXPECT_NE(text.find("#rgb state 5\n"), std::string::npos);
    EXPECT_NE(text.find("#rgb detail-origin 12345 7 scan with spaces.obj\n"), std::string::npos);
    const LoadedMesh loaded = read_obj_text(text, "saved.obj");
    ASSERT_TRUE(loaded.adaptive) << (loaded.warnings.empty() ? "" : loaded.warnings.front());
    expect_on_detail(*loaded.adaptive, *base);
    const rgb::DetailOrigin& origin = loaded.adaptive->base().detail()->origin();
    EXPECT_EQ(origin.source, "scan with spaces.obj");
    EXPECT_EQ(origin.source_triangles, 12345u);
    EXPECT_EQ(origin.nearest_points, 7u);
    // The v lines are the displayed mesh (what other readers see): loaded as plain positions, the same.
    std::size_t i = 0;
    for (rgb::VertexId v : loaded.adaptive->vertices()) ASSERT_EQ(loaded.positions[i++], rgb::displayed_position(*loaded.adaptive, v));
    // Refined further and brought back to level 0 from the reloaded file alone.
    rgb::Mesh resumed = *loaded.adaptive;
    rgb::set_level(resumed, 4, rgb::Sphere{{0, 0, 1}, 0.5});
    expect_on_detail(resumed, *base);
    rgb::set_level(resumed, 0);
    expect_on_detail(resumed, *base);
    EXPECT_EQ(resumed.num_vertices(), 6u);
    // Saved again: the same bytes as the detail saved first, at the same mesh.
    rgb::Mesh again = *loaded.adaptive;
    EXPECT_EQ(format_obj(again, {}), text);
}

TEST(DetailRoundTrip, EditsAreCaught) {
    rgb::Mesh mesh(cage_with_detail());
    rgb::set_level(mesh, 2);
    const std::string text = format_obj(mesh, {});
    // A changed detail value no longer gives the v lines: loaded as a plain mesh, with the reason.
    std::string changed = text;
    const std::size_t d = changed.find("#rgb d ");
    ASSERT_NE(d, std::string::npos);
    const std::size_t first_end = changed.find(' ', d + 7);
    changed.replace(d + 7, first_end - (d + 7), "0.123");
    const LoadedMesh plain = read_obj_text(changed, "changed.obj");
    EXPECT_FALSE(plain.adaptive);
    ASSERT_FALSE(plain.warnings.empty());
    EXPECT_NE(plain.warnings.front().find("does not match the file"), std::string::npos) << plain.warnings.front();
    // A section that announces more than it holds names its line.
    std::string short_section = text;
    const std::size_t header = short_section.find("#rgb section detail ");
    ASSERT_NE(header, std::string::npos);
    short_section.insert(header + 20, "1");
    EXPECT_THROW(read_obj_text(short_section, "short.obj"), ObjError);
}

}  // namespace
}  // namespace rgbio
