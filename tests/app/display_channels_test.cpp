// What the editor displays of a file's vertex colours and texture coordinates is what it saves: after
// adaptive edits, each displayed corner's colour and UV equal those of the same corner in the OBJ the
// document writes (rgb/values/vertex_channel.h, rgb/values/mesh_uvs.h), read back by the OBJ reader. The display
// follows the edits slot by slot (Document::geometry), so this checks its incremental updates, and
// then its rebuild.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "app/document.h"
#include "io/obj_reader.h"
#include "rgb/lod/requests.h"
#include "support/set_level.h"

namespace app {
namespace {

constexpr int kCells = 4;

// A flat kCells x kCells grid with colours that no linear rule reproduces, and texture coordinates
// bent the same way, cut by a UV seam down the middle (the right half's UVs shifted by 2 in u).
std::filesystem::path write_grid() {
    // A folder per test (its parameter too): ctest runs the instances at once, in processes of their own.
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(test->test_suite_name()) + "." + test->name();
    std::replace(name.begin(), name.end(), '/', '_');
    const std::filesystem::path folder = std::filesystem::path(::testing::TempDir()) / ("display_channels_" + name);
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    const std::filesystem::path path = folder / "grid.obj";
    std::ofstream obj(path);
    obj.precision(17);
    const int row = kCells + 1;
    for (int y = 0; y <= kCells; ++y)
        for (int x = 0; x <= kCells; ++x) {
            const double s = std::sin(1.7 * x + 0.9 * y);
            obj << "v " << x << ' ' << y << " 0 " << 0.5 + 0.4 * s << ' ' << (x * y % 3) / 2.0 << ' ' << 0.5 - 0.3 * std::cos(2.3 * y) << '\n';
        }
    // vt 1 .. row*row: the left half's, vt row*row+1 ..: the right half's (the same bent, shifted).
    for (double shift : {0.0, 2.0})
        for (int y = 0; y <= kCells; ++y)
            for (int x = 0; x <= kCells; ++x) obj << "vt " << shift + (x + 0.1 * y * y) / kCells << ' ' << (y + 0.05 * x * x) / kCells << '\n';
    for (int y = 0; y < kCells; ++y)
        for (int x = 0; x < kCells; ++x) {
            const int a = y * row + x + 1, b = a + 1, c = a + row + 1, d = a + row;
            const int t = x < kCells / 2 ? 0 : row * row;
            obj << "f " << a << '/' << a + t << ' ' << b << '/' << b + t << ' ' << c << '/' << c + t << '\n';
            obj << "f " << a << '/' << a + t << ' ' << c << '/' << c + t << ' ' << d << '/' << d + t << '\n';
        }
    return path;
}

// A colour as the display's RGBA8, rounded here without the renderer's helper.
std::uint32_t rgba8(const glm::dvec3& colour) {
    std::uint32_t packed = 0xffu << 24;
    for (int k = 0; k < 3; ++k)
        packed |= static_cast<std::uint32_t>(std::lround(std::clamp(static_cast<float>(colour[k]), 0.0f, 1.0f) * 255.0f)) << (8 * k);
    return packed;
}

// Each live face of the document's display against the face of `saved` with the same corners (found
// by position, which the OBJ writes with 17 digits: the display's floats are those doubles rounded).
void expect_display_is_file(Document& document, const rgbio::LoadedMesh& saved) {
    const render::SurfaceGeometry& geometry = document.geometry();
    const rgb::Mesh& mesh = document.mesh();
    ASSERT_EQ(saved.triangles.size(), mesh.num_faces());
    ASSERT_EQ(saved.colours.size(), saved.positions.size());
    ASSERT_EQ(saved.triangle_texcoords.size(), saved.triangles.size());
    std::map<std::array<float, 3>, std::uint32_t> vertex_at;
    for (std::uint32_t i = 0; i < saved.positions.size(); ++i) {
        const glm::vec3 p(saved.positions[i]);
        ASSERT_TRUE(vertex_at.emplace(std::array<float, 3>{p.x, p.y, p.z}, i).second) << "positions tell the vertices apart";
    }
    // Faces by their corners, starting at the smallest index (the writer keeps the orientation).
    std::map<std::array<std::uint32_t, 3>, std::pair<std::uint32_t, int>> face_of;
    for (std::uint32_t t = 0; t < saved.triangles.size(); ++t) {
        const rgb::Triangle& v = saved.triangles[t];
        const int first = static_cast<int>(std::min_element(v.begin(), v.end()) - v.begin());
        face_of[{v[first], v[(first + 1) % 3], v[(first + 2) % 3]}] = {t, first};
    }
    std::size_t compared = 0;
    for (rgb::FaceId f : mesh.faces()) {
        std::array<std::uint32_t, 3> v{};
        for (int c = 0; c < 3; ++c) {
            const glm::vec3& p = geometry.vertices()[3 * f.idx + c].position;
            const auto found = vertex_at.find({p.x, p.y, p.z});
            ASSERT_NE(found, vertex_at.end()) << "face " << f.idx << " corner " << c;
            v[c] = found->second;
        }
        const int first = static_cast<int>(std::min_element(v.begin(), v.end()) - v.begin());
        const auto face = face_of.find({v[first], v[(first + 1) % 3], v[(first + 2) % 3]});
        ASSERT_NE(face, face_of.end()) << "face " << f.idx << " is in the file";
        for (int c = 0; c < 3; ++c) {
            const int file_corner = (face->second.second + (c - first) + 3) % 3;
            const render::AppearanceVertex& shown = geometry.appearance_vertices()[3 * f.idx + c];
            const glm::dvec2& uv = saved.texcoords[saved.triangle_texcoords[face->second.first][file_corner]];
            EXPECT_EQ(shown.texcoord, glm::vec2(uv)) << "face " << f.idx << " corner " << c;
            EXPECT_EQ(shown.vertex_rgba, rgba8(saved.colours[v[c]])) << "face " << f.idx << " corner " << c;
            ++compared;
        }
    }
    EXPECT_EQ(compared, 3 * mesh.num_faces());
}

class DisplayChannels : public ::testing::TestWithParam<render::PositionSource> {};

TEST_P(DisplayChannels, DisplayedColoursAndUvsAreTheSavedFilesAfterAdaptiveEdits) {
    const std::filesystem::path grid = write_grid();
    Document document;
    document.set_position_source(GetParam());
    document.open(grid.string());
    ASSERT_NE(document.appearance(), nullptr);
    const auto saved_positions = GetParam() == render::PositionSource::Limit ? rgbio::SavedPositions::Limit : rgbio::SavedPositions::Displayed;
    const std::filesystem::path out = grid.parent_path() / "saved.obj";
    // Refine a region across the seam, then coarsen part of it: both add and remove faces.
    const std::array<std::pair<int, rgb::Sphere>, 3> edits{{{3, rgb::Sphere{{1.6, 2.2, 0.0}, 1.3}},
                                                           {1, rgb::Sphere{{1.0, 2.0, 0.0}, 0.6}},
                                                           {2, rgb::Sphere{{3.5, 0.5, 0.0}, 1.0}}}};
    for (const auto& [level, sphere] : edits) {
        SCOPED_TRACE(testing::Message() << "after set_level " << level);
        rgbtest::set_level(document.mesh(), level, sphere);
        rgbio::SaveOptions options;
        options.positions = saved_positions;
        document.save(out.string(), options);
        expect_display_is_file(document, rgbio::read_obj_file(out.string()));
    }
    // A rebuild of the display (after switching positions there and back) computes every corner at
    // once, in parallel: the same values.
    const render::PositionSource other =
        GetParam() == render::PositionSource::Limit ? render::PositionSource::Displayed : render::PositionSource::Limit;
    document.set_position_source(other);
    document.set_position_source(GetParam());
    expect_display_is_file(document, rgbio::read_obj_file(out.string()));
    // Another face-varying option moves the UVs along the boundary and the seam: shown as saved.
    document.set_uv_interpolation(rgb::UvInterpolation::None);
    rgbio::SaveOptions options;
    options.positions = saved_positions;
    document.save(out.string(), options);
    expect_display_is_file(document, rgbio::read_obj_file(out.string()));
}

INSTANTIATE_TEST_SUITE_P(Positions, DisplayChannels, ::testing::Values(render::PositionSource::Displayed, render::PositionSource::Limit),
                         [](const auto& info) { return info.param == render::PositionSource::Limit ? "Limit" : "Displayed"; });

}  // namespace
}  // namespace app
