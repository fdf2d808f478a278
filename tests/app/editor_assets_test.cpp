// A file's materials, groups, texture coordinates and colours in the editor: opening it shows them
// (the document's appearance), painting keeps them, and Save writes the labels back with an mtllib
// that still leads to the library from another folder, as OBJ or glTF.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "app/editor.h"
#include "editor_fixture.h"
#include "io/base_attributes.h"
#include "io/obj_reader.h"
#include "render/surface_appearance.h"

namespace app {
namespace {

using test::kViewport;
using test::fresh_folder;

constexpr int kGridCells = 4;

// A flat kGridCells x kGridCells grid facing +z with texture coordinates (x, y) / kGridCells and vertex colours
// (x / kGridCells, y / kGridCells, 0.5), material "left" (red) or "right" (blue) by column half and group
// "bottom" or "top" by row half, and its library.
void write_grid(const std::filesystem::path& folder) {
    std::ofstream mtl(folder / "grid.mtl");
    mtl << "newmtl left\nKd 1 0 0\nnewmtl right\nKd 0 0 1\n";
    std::ofstream obj(folder / "grid.obj");
    obj << "mtllib grid.mtl\n";
    for (int y = 0; y <= kGridCells; ++y)
        for (int x = 0; x <= kGridCells; ++x)
            obj << "v " << x << ' ' << y << " 0 " << double(x) / kGridCells << ' ' << double(y) / kGridCells << " 0.5\nvt "
                << double(x) / kGridCells << ' ' << double(y) / kGridCells << '\n';
    for (int y = 0; y < kGridCells; ++y)
        for (int x = 0; x < kGridCells; ++x) {
            const int a = y * (kGridCells + 1) + x + 1, b = a + 1, c = a + kGridCells + 2, d = a + kGridCells + 1;
            obj << "g " << (y < kGridCells / 2 ? "bottom" : "top") << "\nusemtl " << (x < kGridCells / 2 ? "left" : "right") << '\n';
            obj << "f " << a << '/' << a << ' ' << b << '/' << b << ' ' << c << '/' << c << '\n';
            obj << "f " << a << '/' << a << ' ' << c << '/' << c << ' ' << d << '/' << d << '\n';
        }
}

TEST(EditorAssets, OpeningShowsTheFilesLookAndSavingKeepsItsLabels) {
    const std::filesystem::path in = fresh_folder("assets_in"), out = fresh_folder("assets_out") / "deeper";
    std::filesystem::create_directories(out);
    write_grid(in);
    Editor editor(kViewport);
    ASSERT_TRUE(editor.open((in / "grid.obj").string())) << editor.message();

    const std::shared_ptr<const render::SurfaceAppearance>& look = editor.document().appearance();
    ASSERT_NE(look, nullptr);
    ASSERT_EQ(look->face_colours.size(), 2u * kGridCells * kGridCells);
    ASSERT_TRUE(look->uvs.has_value());
    ASSERT_EQ(look->uvs->corners.size(), 2u * kGridCells * kGridCells);
    ASSERT_EQ(look->vertex_colours.size(), std::size_t{(kGridCells + 1) * (kGridCells + 1)});
    const rgb::BaseMesh& base = editor.document().mesh().base();
    for (std::uint32_t f = 0; f < base.num_faces(); ++f) {
        glm::dvec3 centroid(0.0);
        for (int c = 0; c < 3; ++c) {
            const glm::dvec3& p = base.position(base.face(f)[c]);
            centroid += p / 3.0;
            EXPECT_EQ(look->uvs->values[look->uvs->corners[f][c]], glm::dvec2(p.x / kGridCells, p.y / kGridCells));
        }
        EXPECT_EQ(*look->face_colours[f], centroid.x < kGridCells / 2 ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1)) << "face " << f;
    }

    const std::size_t before = editor.document().mesh().num_faces();
    editor.brush().target_level = 3;
    editor.brush().radius_px = 60.0f;
    editor.mouse_moved({0.3f * kViewport.x, 0.5f * kViewport.y});
    editor.mouse_pressed(MouseButton::Left, {});
    editor.mouse_moved({0.7f * kViewport.x, 0.5f * kViewport.y});
    editor.mouse_released(MouseButton::Left);
    editor.finish_work();
    ASSERT_GT(editor.document().mesh().num_faces(), before) << "the stroke refined the grid";

    editor.request_save_as((out / "painted.obj").string());
    editor.finish_work();
    ASSERT_FALSE(editor.message_is_error()) << editor.message();
    std::vector<std::string> warnings;
    const rgbio::LoadedAsset saved = rgbio::load_asset((out / "painted.obj").string(), &warnings);
    EXPECT_EQ(saved.mesh.num_faces(), editor.document().mesh().num_faces());
    const rgbio::LoadedMesh input = rgbio::read_obj_file((in / "grid.obj").string());
    EXPECT_EQ(saved.attributes->labels.materials, input.face_materials);
    EXPECT_EQ(saved.attributes->labels.groups, input.face_groups);
    const rgbio::LoadedMesh written = rgbio::read_obj_file((out / "painted.obj").string());
    ASSERT_EQ(written.materials.size(), 2u) << "the mtllib line leads to grid.mtl from the other folder";
    EXPECT_EQ(written.materials[1].diffuse, glm::dvec3(0, 0, 1));

    editor.request_save_as((out / "painted.glb").string());
    editor.finish_work();
    ASSERT_FALSE(editor.message_is_error()) << editor.message();
    std::ifstream glb(out / "painted.glb", std::ios::binary);
    std::string magic(4, '\0');
    glb.read(magic.data(), 4);
    EXPECT_EQ(magic, "glTF");
}

// The samples that ship in assets/ (made by assets/make_samples.py) open with their look: the
// textured box with texture coordinates and its brick image, the coloured box with a colour per
// vertex, (1 + its direction from the centre) / 2.
TEST(EditorAssets, TheShippedSamplesOpenWithTheirTextureAndColours) {
    constexpr std::size_t kSampleFaces = 192, kSampleVertices = 98;
    Editor editor(kViewport);
    ASSERT_TRUE(editor.open(test::asset_path("textured.obj"))) << editor.message();
    ASSERT_FALSE(editor.message_is_error()) << editor.message();
    const std::shared_ptr<const render::SurfaceAppearance> textured = editor.document().appearance();
    ASSERT_NE(textured, nullptr);
    ASSERT_EQ(editor.document().mesh().base().num_faces(), kSampleFaces);
    ASSERT_TRUE(textured->uvs.has_value());
    ASSERT_EQ(textured->uvs->corners.size(), kSampleFaces);
    for (const glm::dvec2& uv : textured->uvs->values) {
        EXPECT_TRUE(uv.x >= 0.0 && uv.x <= 1.0 && uv.y >= 0.0 && uv.y <= 1.0) << uv.x << ", " << uv.y;
        EXPECT_DOUBLE_EQ(uv.x * 4.0, std::round(uv.x * 4.0)) << "a corner of the 4 x 4 grid on each cube face";
    }
    EXPECT_EQ(textured->face_textures, std::vector<std::uint32_t>(kSampleFaces, 0u)) << "every face shows layer 0, its map_Kd";
    const render::TextureLayers& layers = textured->textures;
    ASSERT_EQ(layers.count(), 1u);
    ASSERT_EQ(layers.width, 64);
    ASSERT_EQ(layers.height, 64);
    // The script's pattern: the image's top row (the layer's last, rows bottom-up) is mortar, the
    // brick below it at the left the first shade.
    const auto pixel = [&](int x, int image_y) {
        const std::size_t at = 4 * (std::size_t(63 - image_y) * 64 + std::size_t(x));
        return glm::ivec3(layers.rgba[at], layers.rgba[at + 1], layers.rgba[at + 2]);
    };
    EXPECT_EQ(pixel(5, 0), glm::ivec3(215, 210, 200));
    EXPECT_EQ(pixel(5, 4), glm::ivec3(150, 60, 40));

    ASSERT_TRUE(editor.open(test::asset_path("coloured.obj"))) << editor.message();
    const std::shared_ptr<const render::SurfaceAppearance> coloured = editor.document().appearance();
    ASSERT_NE(coloured, nullptr);
    const rgb::BaseMesh& base = editor.document().mesh().base();
    ASSERT_EQ(base.num_vertices(), kSampleVertices);
    ASSERT_EQ(coloured->vertex_colours.size(), kSampleVertices);
    EXPECT_FALSE(coloured->uvs.has_value());
    for (std::uint32_t v = 0; v < base.num_vertices(); ++v) {
        const glm::dvec3 expected = (1.0 + glm::normalize(base.position(v))) / 2.0;
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(coloured->vertex_colours[v][k], expected[k], 2e-6) << "vertex " << v;
    }
}

}  // namespace
}  // namespace app
