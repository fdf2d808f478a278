// Headless screenshots (OSMesa) checked against what the mesh says they must show.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "gl_test_support.h"
#include "render/headless.h"
#include "render/surface_geometry.h"
#include "rgb/lod/refine.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/loop_geometry.h"
#include "test_meshes.h"
#include "support/set_level.h"

namespace {

using render::Colouring;
using render::HeadlessView;
using render::Image;
using render::RenderOptions;
using render_test::count_pixels;

RenderOptions rgb_options(bool wire) {
    RenderOptions options;
    options.shading = render::Shading::Flat;
    options.colouring = Colouring::RgbType;
    options.wireframe = wire;
    return options;
}

// The camera render_headless uses for this mesh.
render::OrbitCamera camera_for(const rgb::Mesh& mesh, const HeadlessView& view) {
    render::SurfaceGeometry geometry;
    geometry.rebuild(mesh);
    return render::framing_camera(geometry.bounds(mesh), view);
}

TEST(Screenshot, SameInputGivesTheSameBytes) {
    rgb::Mesh mesh = render_test::icosphere(2);
    rgbtest::set_level(mesh, 2, rgb::Sphere{{0.0, 0.0, 1.0}, 0.5});
    const HeadlessView view{{160, 120}, 30.0f, 20.0f};
    const Image first = render::render_headless(mesh, rgb_options(true), view);
    const Image second = render::render_headless(mesh, rgb_options(true), view);
    EXPECT_EQ(first.rgba, second.rgba);

    const std::string png = render::encode_png(first);
    EXPECT_EQ(png, render::encode_png(second));
    const Image back = render::decode_png(png);
    EXPECT_EQ(back.rgba, first.rgba) << "the PNG round trip is lossless and keeps the row order";
}

TEST(Screenshot, BaseMeshInRgbModeIsAllGreen) {
    rgb::Mesh mesh = render_test::icosphere(2);
    const auto counts = count_pixels(render::render_headless(mesh, rgb_options(true), {{200, 150}, 30.0f, 20.0f}));
    EXPECT_EQ(counts.red, 0u);
    EXPECT_EQ(counts.blue, 0u);
    EXPECT_GT(counts.green, 200u * 150u / 5) << "the framed sphere covers a good part of the view";
}

// Seen from straight above, the flat grid's triangles do not overlap, so the pixels of each colour
// must add up to the screen area of that colour's triangles, up to the pixels along the outline of
// the colour's region: a pixel centre can fall on the wrong side only within half a pixel diagonal
// (sqrt(2)/2) of it, a band of area at most sqrt(2) * outline length.
TEST(Screenshot, ColourAreasMatchTheProjectedTriangles) {
    rgb::Mesh mesh = render_test::grid(4);
    rgbtest::set_level(mesh, 3, rgb::Sphere{{-1.0, 0.0, -1.0}, 1.0});
    const HeadlessView view{{400, 400}, 0.0f, 90.0f};
    const render_test::PixelCounts counts = count_pixels(render::render_headless(mesh, rgb_options(false), view));

    const render::OrbitCamera camera = camera_for(mesh, view);
    const glm::mat4 vp = camera.view_projection(1.0f);
    const auto to_pixels = [&](rgb::VertexId v) {
        const glm::vec4 clip = vp * glm::vec4(glm::vec3(rgb::displayed_position(mesh, v)), 1.0f);
        return (glm::vec2(clip) / clip.w + 1.0f) * 0.5f * glm::vec2(view.size);
    };
    double area[3] = {0, 0, 0};
    double outline[3] = {0, 0, 0};
    for (rgb::FaceId f : mesh.faces()) {
        const int c = static_cast<int>(mesh.colour(f));
        const auto& v = mesh.face_vertices(f);
        const glm::vec2 p0 = to_pixels(v[0]), p1 = to_pixels(v[1]), p2 = to_pixels(v[2]);
        const glm::vec2 e1 = p1 - p0, e2 = p2 - p0;
        area[c] += 0.5 * std::abs(e1.x * e2.y - e1.y * e2.x);
        for (int i = 0; i < 3; ++i) {
            const rgb::HalfedgeId h = rgb::Mesh::halfedge(f, i);
            if (mesh.is_boundary(h) || mesh.colour(rgb::Mesh::face(mesh.opposite(h))) != mesh.colour(f))
                outline[c] += glm::distance(to_pixels(mesh.from_vertex(h)), to_pixels(mesh.to_vertex(h)));
        }
    }
    ASSERT_GT(area[1], 100.0) << "the refinement made red triangles";
    ASSERT_GT(area[2], 100.0) << "the refinement made blue triangles";
    const double got[3] = {static_cast<double>(counts.green), static_cast<double>(counts.red), static_cast<double>(counts.blue)};
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(got[c], area[c], std::sqrt(2.0) * outline[c]) << rgb::colour_name(static_cast<rgb::Colour>(c));
    EXPECT_EQ(counts.neutral, 0u);
}

// An inscribed polyhedron's silhouette lies between those of its inner sphere (touching the face
// planes) and its circumsphere; a centred sphere of radius r seen from distance d under vertical
// field of view fov covers a disc of radius tan(asin(r / d)) / tan(fov / 2) * H / 2 pixels. Pixel
// sampling adds at most sqrt(2)/2 pixel around the outline.
TEST(Screenshot, SphereSilhouetteCoversItsProjectedArea) {
    rgb::Mesh mesh = render_test::icosphere(3);
    const HeadlessView view{{300, 300}, 40.0f, 25.0f};
    const render_test::PixelCounts counts = count_pixels(render::render_headless(mesh, RenderOptions{}, view));
    const double covered = static_cast<double>(view.size.x * view.size.y) - static_cast<double>(counts.background);

    double inner = 1.0;
    for (rgb::FaceId f : mesh.faces()) {
        const auto& v = mesh.face_vertices(f);
        const glm::dvec3 p0 = mesh.insertion_position(v[0]);
        const glm::dvec3 n = glm::normalize(glm::cross(mesh.insertion_position(v[1]) - p0, mesh.insertion_position(v[2]) - p0));
        inner = std::min(inner, std::abs(glm::dot(n, p0)));
    }
    const render::OrbitCamera camera = camera_for(mesh, view);
    ASSERT_LT(glm::length(camera.target), 1e-5f) << "the icosphere is centrally symmetric";
    const double half_fov = 0.5 * camera.fov_y_deg * std::numbers::pi / 180.0;
    const auto disc_radius = [&](double r) { return std::tan(std::asin(r / camera.distance)) / std::tan(half_fov) * view.size.y / 2; };
    const double r_in = disc_radius(inner), r_out = disc_radius(1.0);
    const double band = std::sqrt(2.0) * std::numbers::pi * r_out;
    EXPECT_GE(covered, std::numbers::pi * r_in * r_in - band);
    EXPECT_LE(covered, std::numbers::pi * r_out * r_out + band);
}

// The icosphere refined to `level` around its +z pole, in the level colouring, seen from +z.
Image level_picture(int level) {
    rgb::Mesh mesh = render_test::icosphere(1);
    rgbtest::set_level(mesh, level, rgb::Sphere{{0.0, 0.0, 1.0}, 0.7});
    int max_level = 0;
    for (rgb::FaceId f : mesh.faces()) max_level = std::max(max_level, mesh.level(f));
    EXPECT_EQ(max_level, level);
    RenderOptions options;
    options.colouring = Colouring::Level;
    return render::render_headless(mesh, options, HeadlessView{{240, 200}, 0.0f, 0.0f});
}

// The legend stacks one swatch per level in the bottom-left corner, finest on top, and each level
// has one fixed colour (README: a level looks the same in every picture whatever else is on screen),
// blue at level 0 and each differing from its neighbours. So pictures with different finest levels
// show the same swatches for the levels they share, and the mesh shows the top swatch's colour.
TEST(Screenshot, LevelLegendShowsEachLevelsColourTheSameInEveryPicture) {
    const Image two = level_picture(2), three = level_picture(3);
    // Column 20 runs through the swatches (12 to 28 pixels from the left), left of the sphere.
    const std::vector<render_test::Swatch> legend_two = render_test::legend_column(two, 20, 12);
    const std::vector<render_test::Swatch> legend_three = render_test::legend_column(three, 20, 12);
    ASSERT_EQ(legend_two.size(), 3u) << "levels 0 to 2";
    ASSERT_EQ(legend_three.size(), 4u) << "levels 0 to 3";
    EXPECT_EQ(legend_two.back().kind, render_test::PixelClass::Blue) << "level 0";
    for (std::size_t level = 0; level < 3; ++level)
        EXPECT_EQ(legend_two[2 - level].colour, legend_three[3 - level].colour) << "level " << level;
    for (std::size_t i = 0; i + 1 < legend_three.size(); ++i)
        EXPECT_NE(legend_three[i].colour, legend_three[i + 1].colour) << "levels " << 3 - i << " and " << 2 - i;

    // The same colours on the mesh: its coarsest faces in level 0's class, its finest in level 3's.
    const render_test::PixelClass finest = legend_three.front().kind;
    ASSERT_NE(finest, render_test::PixelClass::Neutral) << "the top swatch has a clear hue";
    const render_test::PixelCounts counts = count_pixels(three);
    const auto count_of = [&](render_test::PixelClass c) {
        return c == render_test::PixelClass::Red ? counts.red : c == render_test::PixelClass::Green ? counts.green : counts.blue;
    };
    std::size_t swatches_of_class = 0;
    for (const render_test::Swatch& s : legend_three) swatches_of_class += s.kind == finest;
    EXPECT_GT(count_of(finest), swatches_of_class * 16u * 16u + 500u);
    std::size_t blue_swatches = 0;
    for (const render_test::Swatch& s : legend_three) blue_swatches += s.kind == render_test::PixelClass::Blue;
    EXPECT_GT(counts.blue, blue_swatches * 16u * 16u + 500u);
}

TEST(Screenshot, BrushCursorAndBaseOverlayAddOnlyWhatTheyDraw) {
    rgb::Mesh mesh = render_test::icosphere(0);
    rgb::refine_uniform(mesh, 2);
    const HeadlessView view{{200, 200}, 0.0f, 0.0f};
    const Image plain = render::render_headless(mesh, RenderOptions{}, view);
    RenderOptions with_brush;
    with_brush.brush = render::BrushCursor{{0.0f, 0.0f, 0.8f}, 0.3f};
    RenderOptions with_cage;
    with_cage.base_mesh_overlay = true;
    const auto orange = [](const Image& image) {
        std::size_t n = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                const glm::u8vec4 p = image.pixel(x, y);
                n += p.r > 150 && p.r > p.g + 40 && p.g > p.b + 40;
            }
        return n;
    };
    const auto dark = [](const Image& image) {
        std::size_t n = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) n += image.pixel(x, y).r < 50;
        return n;
    };
    EXPECT_EQ(orange(plain), 0u);
    EXPECT_GT(orange(render::render_headless(mesh, with_brush, view)), 50u) << "a ring about 2 pixels wide";
    EXPECT_EQ(dark(plain), 0u) << "the lit grey surface never gets that dark";
    EXPECT_GT(dark(render::render_headless(mesh, with_cage, view)), 50u) << "the icosahedron's edges";
}

// Framing and shading do not depend on the unit: the same sphere at 1e-20, 1e10, 1e12 (the largest
// coordinate the loader accepts) or 2^-100 looks as it does at unit size, up to rounding along edges
// (1e10 is not a power of two, so its positions round differently). These scales used to give black
// (normals overflowing float) or flat, wrongly lit images.
TEST(Screenshot, MeshesFarFromUnitSizeLookAsAtUnitSize) {
    const HeadlessView view{{160, 120}, 30.0f, 20.0f};
    RenderOptions flat_wire = rgb_options(true);
    RenderOptions brush;
    brush.brush = render::BrushCursor{{0.0f, 0.0f, 1.0f}, 0.4f};
    for (const RenderOptions& options : {RenderOptions{}, flat_wire, brush}) {
        rgb::Mesh unit = render_test::icosphere(2);
        const Image expected = render::render_headless(unit, options, view);
        for (double scale : {1e-20, 1e10, 1e12, std::ldexp(1.0, -100)}) {
            rgb::Mesh scaled = render_test::icosphere(2, scale);
            RenderOptions scaled_options = options;
            if (options.brush) scaled_options.brush = render::BrushCursor{options.brush->centre * float(scale), options.brush->radius * float(scale)};
            const Image image = render::render_headless(scaled, scaled_options, view);
            std::size_t differing = 0;
            for (std::size_t i = 0; i < image.rgba.size(); i += 4)
                for (std::size_t c = 0; c < 3; ++c)
                    if (std::abs(int{image.rgba[i + c]} - int{expected.rgba[i + c]}) > 2) {
                        ++differing;
                        break;
                    }
            EXPECT_LE(differing, image.rgba.size() / 4 / 200) << "scale " << scale << ": pixels differing from the unit-size image";
        }
    }
}

}  // namespace

namespace {

// One triangle facing +z: seen from +z it shows the plain grey, from -z the back-face colour, so that
// the inside of an open mesh never passes for its outside.
TEST(Screenshot, BackFacesHaveAColourOfTheirOwn) {
    const std::vector<glm::dvec3> p{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    const std::vector<rgb::Triangle> t{{0, 1, 2}};
    rgb::Mesh mesh(p, t);
    const Image front = render::render_headless(mesh, RenderOptions{}, HeadlessView{{64, 64}, 0.0f, 0.0f});
    const Image back = render::render_headless(mesh, RenderOptions{}, HeadlessView{{64, 64}, 180.0f, 0.0f});
    const glm::u8vec4 f = front.pixel(32, 36), b = back.pixel(32, 36);
    EXPECT_LE(std::abs(int{f.r} - int{f.g}), 6) << "the front is grey";
    EXPECT_GT(int{b.r} - int{b.g}, 40) << "the back is reddish";
}

}  // namespace
