// The file's look in the display (render/surface_appearance.h): every corner of the adaptive mesh
// carries its base face's material colour, and the exact vertex colour and texture coordinate
// channels (expected values from linear data: see expect_appearance_of_base_space); incremental updates keep them equal to a rebuild; the checker mode draws the cells those
// texture coordinates say, refined or not; the texture mode draws each material's texture over them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>

#include "gl_test_support.h"
#include "render/colour_map.h"
#include "render/headless.h"
#include "render/mesh_changes.h"
#include "render/surface_geometry.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/mesh.h"
#include "test_meshes.h"
#include "support/set_level.h"

namespace {

using render::AppearanceVertex;
using render::SurfaceAppearance;

constexpr int kCells = 4;

// The grid's look given by linear functions of the base position (x, 0, z) in [-1, 1]^2: texture
// coordinate ((x + 1) / 2, (z + 1) / 2), vertex colour (u, v, 0.25); material colour by the base face
// number, so that it changes from face to face.
glm::vec2 texcoord_at(const glm::dvec3& p) { return {static_cast<float>((p.x + 1) / 2), static_cast<float>((p.z + 1) / 2)}; }
glm::vec3 colour_at(const glm::dvec3& p) { return {texcoord_at(p), 0.25f}; }
glm::vec3 material_of(std::uint32_t base_face) { return {base_face % 2 == 0 ? 1.0f : 0.0f, 0.5f, static_cast<float>(base_face) / 64.0f}; }

// Loop's rules reproduce linear UVs on the grid: every interior vertex has six neighbours placed
// symmetrically, every boundary runs straight, and the UVs keep their corners (the default option).
SurfaceAppearance grid_look(const rgb::Mesh& mesh) {
    SurfaceAppearance look;
    const rgb::BaseMesh& base = mesh.base();
    look.uvs.emplace();
    for (std::uint32_t v = 0; v < base.num_vertices(); ++v) {
        look.vertex_colours.emplace_back(colour_at(base.position(v)));
        look.uvs->values.emplace_back((base.position(v).x + 1) / 2, (base.position(v).z + 1) / 2);
    }
    for (std::uint32_t f = 0; f < base.num_faces(); ++f) {
        look.face_colours.emplace_back(material_of(f));
        look.uvs->corners.push_back(base.face(f));
    }
    return look;
}

std::shared_ptr<const SurfaceAppearance> grid_appearance(const rgb::Mesh& mesh) {
    return std::make_shared<const SurfaceAppearance>(grid_look(mesh));
}

// The base face whose triangle holds `p` strictly inside (found from the grid's layout: the cell and
// the side of its diagonal, test_meshes.cpp).
std::uint32_t base_face_at(const glm::dvec3& p) {
    const double s = (p.x + 1) / 2 * kCells, t = (p.z + 1) / 2 * kCells;
    const int i = static_cast<int>(s), j = static_cast<int>(t);
    const bool below_diagonal = (s - i) > (t - j);  // triangle {(i,j), (i+1,j+1), (i+1,j)}
    return static_cast<std::uint32_t>(2 * (j * kCells + i) + (below_diagonal ? 1 : 0));
}

// One byte of a packed colour.
int byte(std::uint32_t rgba, int k) { return static_cast<int>((rgba >> (8 * k)) & 0xffu); }

void expect_appearance_of_base_space(const rgb::Mesh& mesh, const render::SurfaceGeometry& geometry) {
    const std::span<const AppearanceVertex> look = geometry.appearance_vertices();
    ASSERT_EQ(look.size(), geometry.vertices().size());
    for (rgb::FaceId f : mesh.faces()) {
        glm::dvec3 centroid(0.0);
        for (rgb::VertexId v : mesh.face_vertices(f)) centroid += mesh.base_space_position(v) / 3.0;
        const std::uint32_t material = render::packed_colour(material_of(base_face_at(centroid)));
        for (int c = 0; c < 3; ++c) {
            const AppearanceVertex& a = look[3 * f.idx + c];
            const glm::dvec3 p = mesh.base_space_position(mesh.face_vertices(f)[c]);
            EXPECT_EQ(a.material_rgba, material) << "face " << f.idx;
            EXPECT_NEAR(a.texcoord.x, texcoord_at(p).x, 1e-6);
            EXPECT_NEAR(a.texcoord.y, texcoord_at(p).y, 1e-6);
            // Loop's rules are affine and the colours an affine function of the base positions: a
            // vertex's colour is that function of its displayed position (also at the grid's corners,
            // where the boundary bends and the colours are not those of the base-space position).
            const std::uint32_t colour = render::packed_colour(colour_at(glm::dvec3(geometry.vertices()[3 * f.idx + c].position)));
            for (int k = 0; k < 4; ++k) EXPECT_LE(std::abs(byte(a.vertex_rgba, k) - byte(colour, k)), 1) << "byte " << k;
        }
    }
}

TEST(Appearance, CornersCarryTheirBaseFacesMaterialAndTheExactChannels) {
    rgb::Mesh mesh = render_test::grid(kCells);
    render::MeshChanges changes(mesh);
    render::SurfaceGeometry geometry;
    geometry.set_appearance(grid_appearance(mesh));
    geometry.rebuild(mesh);
    expect_appearance_of_base_space(mesh, geometry);

    for (int target : {3, 1, 4}) {
        SCOPED_TRACE(testing::Message() << "after set_level " << target);
        rgbtest::set_level(mesh, target, rgb::Sphere{{-0.3, 0.0, 0.2}, 0.7});
        geometry.update(mesh, changes);
        changes.clear();
        expect_appearance_of_base_space(mesh, geometry);
        render::SurfaceGeometry fresh;
        fresh.set_appearance(geometry.appearance());
        fresh.rebuild(mesh);
        ASSERT_EQ(fresh.appearance_vertices().size(), geometry.appearance_vertices().size());
        for (std::size_t i = 0; i < fresh.appearance_vertices().size(); ++i)
            ASSERT_EQ(geometry.appearance_vertices()[i], fresh.appearance_vertices()[i]) << "vertex " << i;
    }
}

TEST(Appearance, FacesWithoutDataHaveNone) {
    rgb::Mesh mesh = render_test::grid(1);
    SurfaceAppearance look;
    look.face_colours = {std::nullopt, glm::vec3(0.0f, 1.0f, 0.0f)};
    // Face 1 has no texture coordinates: its corners name a placeholder value of their own.
    look.uvs = rgb::UvChannel{{glm::dvec2(0.5), glm::dvec2(0.0)}, {{0, 0, 0}, {1, 1, 1}}, rgb::UvInterpolation::Corners, {1}};
    look.face_textures = {render::kNoTexture, 0};
    render::SurfaceGeometry geometry;
    geometry.set_appearance(std::make_shared<const SurfaceAppearance>(look));
    geometry.rebuild(mesh);
    const std::span<const AppearanceVertex> a = geometry.appearance_vertices();
    ASSERT_EQ(a.size(), 6u);
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(a[c], (AppearanceVertex{0, 0, glm::vec2(0.5f), render::kNoTexture}));
        EXPECT_EQ(a[3 + c], (AppearanceVertex{0xff00ff00u, 0, glm::vec2(0.0f), render::kNoTexture})) << "no texture without UVs";
    }
    render::SurfaceGeometry plain;
    plain.rebuild(mesh);
    EXPECT_TRUE(plain.appearance_vertices().empty()) << "no second array without an appearance";
}

// Seen from straight above, the checker has kCheckerCells^2 cells of equal screen area, half of them
// light (classified neutral) and half dark (blue), up to the pixels along the cell borders; the cell
// at texture coordinate (0, 0), the grid's corner (-1, 0, -1), is light. Refining changes no pixel
// except along cell borders: the texture coordinates are the same linear function.
TEST(Appearance, CheckerShowsTheTextureCellsRefinedOrNot) {
    rgb::Mesh mesh = render_test::grid(kCells);
    render::RenderOptions options;
    options.colouring = render::Colouring::Checker;
    const render::HeadlessView view{{320, 320}, 0.0f, 90.0f};
    const auto look = grid_appearance(mesh);
    const render::Image flat = render::render_headless(mesh, options, view, look);
    const render_test::PixelCounts counts = render_test::count_pixels(flat);

    render::SurfaceGeometry geometry;
    geometry.rebuild(mesh);
    const render::OrbitCamera camera = render::framing_camera(geometry.bounds(mesh), view);
    const glm::mat4 vp = camera.view_projection(1.0f);
    auto to_pixels = [&](const glm::dvec3& p) {
        const glm::vec4 clip = vp * glm::vec4(glm::vec3(p), 1.0f);
        return (glm::vec2(clip) / clip.w + 1.0f) * 0.5f * glm::vec2(view.size);
    };
    const glm::vec2 corner = to_pixels({-1, 0, -1}), opposite = to_pixels({1, 0, 1});
    const double side = std::abs(opposite.x - corner.x);  // the square's side in pixels
    ASSERT_GT(side, 150.0);
    const double borders = 2.0 * (render::kCheckerCells + 1) * side;
    const double half = side * side / 2;
    EXPECT_NEAR(static_cast<double>(counts.neutral), half, std::sqrt(2.0) * borders);
    EXPECT_NEAR(static_cast<double>(counts.blue), half, std::sqrt(2.0) * borders);
    const double cell = side / render::kCheckerCells;
    const glm::vec2 first_cell = corner + 0.5f * static_cast<float>(cell) * glm::sign(opposite - corner);
    const glm::vec2 second_cell = first_cell + glm::vec2(static_cast<float>(cell) * glm::sign(opposite.x - corner.x), 0.0f);
    // Clip space has y up, images rows from the top.
    auto class_at = [&](const glm::vec2& p) { return render_test::classify(flat, static_cast<int>(p.x), view.size.y - 1 - static_cast<int>(p.y)); };
    EXPECT_EQ(class_at(first_cell), render_test::PixelClass::Neutral);
    EXPECT_EQ(class_at(second_cell), render_test::PixelClass::Blue);

    rgbtest::set_level(mesh, 3, rgb::Sphere{{0.2, 0.0, -0.1}, 0.6});
    const render::Image refined = render::render_headless(mesh, options, view, look);
    std::size_t changed = 0;
    for (int y = 0; y < view.size.y; ++y)
        for (int x = 0; x < view.size.x; ++x) changed += render_test::classify(flat, x, y) != render_test::classify(refined, x, y);
    EXPECT_LT(static_cast<double>(changed), std::sqrt(2.0) * borders);
}

// The grid seen from straight above, and where a point (x, 0, z) of it lands in the image.
struct TopView {
    render::HeadlessView view{{320, 320}, 0.0f, 90.0f};
    glm::mat4 view_projection;

    explicit TopView(const rgb::Mesh& mesh) {
        render::SurfaceGeometry geometry;
        geometry.rebuild(mesh);
        view_projection = render::framing_camera(geometry.bounds(mesh), view).view_projection(1.0f);
    }
    render_test::PixelClass class_at(const render::Image& image, double x, double z) const {
        const glm::vec4 clip = view_projection * glm::vec4(static_cast<float>(x), 0.0f, static_cast<float>(z), 1.0f);
        const glm::vec2 p = (glm::vec2(clip) / clip.w + 1.0f) * 0.5f * glm::vec2(view.size);
        // Clip space has y up, images rows from the top.
        return render_test::classify(image, static_cast<int>(p.x), view.size.y - 1 - static_cast<int>(p.y));
    }
};

// 64 x 64 texels, rows from the top of the image (v = 1) down: the left half (u < 0.5) blue in its
// top half and red in its bottom half, the right half white.
render::Image quadrant_texture() {
    render::Image image{64, 64, std::vector<std::uint8_t>(64 * 64 * 4, 255)};
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 32; ++x) {
            std::uint8_t* texel = &image.rgba[4 * (64 * y + x)];
            texel[0] = y < 32 ? 0 : 255;
            texel[1] = 0;
            texel[2] = y < 32 ? 255 : 0;
        }
    return image;
}

// The grid's faces left of x = 0 (u < 0.5) carry `left_texture`, those right of it no texture and
// the diffuse colour green.
std::shared_ptr<const SurfaceAppearance> textured_grid(const rgb::Mesh& mesh, std::uint32_t left_texture) {
    SurfaceAppearance look = grid_look(mesh);
    const rgb::BaseMesh& base = mesh.base();
    for (std::uint32_t f = 0; f < base.num_faces(); ++f) {
        double x = 0.0;
        for (std::uint32_t v : base.face(f)) x += base.position(v).x / 3.0;
        look.face_textures.push_back(x < 0.0 ? left_texture : render::kNoTexture);
        look.face_colours[f] = x < 0.0 ? glm::vec3(0.5f) : glm::vec3(0.0f, 1.0f, 0.0f);
    }
    look.textures = render::texture_layers({quadrant_texture()});
    return std::make_shared<const SurfaceAppearance>(std::move(look));
}

// Texture coordinate (u, v) = ((x + 1) / 2, (z + 1) / 2): the texture's left half covers x < 0, its
// bottom (red) z < 0 and its top (blue) z > 0; right of x = 0 the material's green. Checked on an 8 x 8
// lattice of points that keeps 1/8 away from every border of those regions.
TEST(Appearance, TextureModeDrawsEachFacesMaterialTextureOverItsUvs) {
    rgb::Mesh mesh = render_test::grid(kCells);
    render::RenderOptions options;
    options.colouring = render::Colouring::Texture;
    const TopView top(mesh);
    const render::Image image = render::render_headless(mesh, options, top.view, textured_grid(mesh, 0));
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) {
            const double x = -0.875 + 0.25 * i, z = -0.875 + 0.25 * j;
            const render_test::PixelClass expected =
                x > 0.0 ? render_test::PixelClass::Green : (z < 0.0 ? render_test::PixelClass::Red : render_test::PixelClass::Blue);
            EXPECT_EQ(top.class_at(image, x, z), expected) << "at x " << x << ", z " << z;
        }
}

// A texture that could not be read shows the checker: cell (i, j) of kCheckerCells per unit of
// texture coordinate in light grey (neutral) where i + j is even, dark blue where odd.
TEST(Appearance, AnUnreadableTextureShowsTheChecker) {
    rgb::Mesh mesh = render_test::grid(kCells);
    render::RenderOptions options;
    options.colouring = render::Colouring::Texture;
    const TopView top(mesh);
    const render::Image image = render::render_headless(mesh, options, top.view, textured_grid(mesh, render::kUnreadableTexture));
    const int cells = static_cast<int>(render::kCheckerCells);
    for (int i = 0; i < cells / 2; ++i)
        for (int j = 0; j < cells; ++j) {
            const double u = (i + 0.5) / cells, v = (j + 0.5) / cells;
            const render_test::PixelClass expected = (i + j) % 2 == 0 ? render_test::PixelClass::Neutral : render_test::PixelClass::Blue;
            EXPECT_EQ(top.class_at(image, 2 * u - 1, 2 * v - 1), expected) << "cell " << i << ", " << j;
        }
    EXPECT_EQ(top.class_at(image, 0.5, 0.5), render_test::PixelClass::Green) << "untextured faces keep their colour";
}

}  // namespace
