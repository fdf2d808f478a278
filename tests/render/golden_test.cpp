// Golden images: whole pictures a person has looked at, compared with a small per-pixel tolerance.
// The tests only read them, whatever the environment says; a person rewrites them with the separate
// command `cmake --build BUILD --target render_golden_update` (golden_update.cpp) and reviews them
// before committing (golden/README.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec4.hpp>

#include "gl_test_support.h"
#include "golden_cases.h"
#include "render/headless.h"
#include "render/surface_geometry.h"
#include "rgb/mesh/mesh.h"

namespace {

using render::Image;
using render_test::GoldenCase;
using render_test::locally_refined_sphere;

// Per channel, out of 255: absorbs rounding differences between llvmpipe builds, far below any
// change of colour, shading or geometry a person would notice.
constexpr int kTolerance = 2;

class Golden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, MatchesTheReviewedImage) {
    const GoldenCase& c = GetParam();
    const Image image = render_test::render_golden(c);
    const std::filesystem::path path = std::filesystem::path(RGBSUB_GOLDEN_DIR) / (c.name + ".png");
    const Image golden = render::read_image(path);
    ASSERT_EQ(golden.width, image.width);
    ASSERT_EQ(golden.height, image.height);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < image.rgba.size(); ++i)
        differing += std::abs(int{image.rgba[i]} - int{golden.rgba[i]}) > kTolerance;
    EXPECT_EQ(differing, 0u) << "channels differ by more than " << kTolerance << " from " << path;
}

INSTANTIATE_TEST_SUITE_P(Images, Golden, ::testing::ValuesIn(render_test::golden_cases()),
                         [](const auto& info) { return info.param.name; });

// ---- what each reviewed image must show ------------------------------------------------------
// Checked on the PNG files themselves, so that images rewritten by mistake (and then matched by the
// comparison above) still fail: silhouettes, colours and where they sit, the legend's order, the
// brush ring and the cage.

constexpr glm::ivec2 kGoldenSize{256, 256};

class GoldenImage : public ::testing::Test {
protected:
    static Image load(const std::string& name) { return render::read_image(std::filesystem::path(RGBSUB_GOLDEN_DIR) / (name + ".png")); }
    // The camera render_headless framed `bounds` with (256x256, azimuth 30, elevation 20).
    void frame(const render::BoundingSphere& bounds) {
        camera_ = render::framing_camera(bounds, {kGoldenSize, 30.0f, 20.0f});
    }
    glm::vec2 pixel_of(const glm::vec3& p) const {
        const glm::vec4 clip = camera_.view_projection(1.0f) * glm::vec4(p, 1.0f);
        return {(clip.x / clip.w + 1.0f) * 0.5f * kGoldenSize.x, (1.0f - clip.y / clip.w) * 0.5f * kGoldenSize.y};
    }
    // Screen radius of a sphere of radius r around p (seen near the view axis).
    float disc_radius(const glm::vec3& p, float r) const {
        const float distance = glm::distance(camera_.eye(), p);
        return std::tan(std::asin(r / distance)) / std::tan(glm::radians(0.5f * camera_.fov_y_deg)) * 0.5f * kGoldenSize.y;
    }
    render::OrbitCamera camera_;
};

bool is_white(glm::u8vec4 p) { return p.r == 255 && p.g == 255 && p.b == 255; }
bool is_dark(glm::u8vec4 p) { return std::max({p.r, p.g, p.b}) < 70; }
// The wire's dark grey (0.12, 0.12, 0.12), possibly blended with the face under it: no hue of a
// shaded face, unlike the dark flanks of faces seen at a grazing angle.
bool is_wire(glm::u8vec4 p) { return std::max({p.r, p.g, p.b}) < 110 && std::max({p.r, p.g, p.b}) - std::min({p.r, p.g, p.b}) < 25; }

// Every drawn pixel lies within the projected unit sphere, which holds both test meshes (their
// control vertices lie on it and Loop positions are averages of them).
void expect_inside_unit_sphere(const Image& image, glm::vec2 centre, float radius) {
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (!is_white(image.pixel(x, y))) {
                ASSERT_LE(glm::distance(glm::vec2(x + 0.5f, y + 0.5f), centre), radius + 2.0f) << "pixel " << x << "," << y;
            }
}

// Pixels within `radius` of `centre` that pass `test`, as a fraction of the drawn pixels there.
template <class Test>
double density(const Image& image, glm::vec2 centre, float radius, Test test) {
    std::size_t hits = 0, drawn = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            if (glm::distance(glm::vec2(x + 0.5f, y + 0.5f), centre) > radius || is_white(image.pixel(x, y))) continue;
            ++drawn;
            hits += test(image.pixel(x, y));
        }
    return drawn == 0 ? 0.0 : static_cast<double>(hits) / static_cast<double>(drawn);
}

// Drawn pixels within `radius` of `centre` whose right neighbour differs by more than 8 of 255 in
// some channel, as a fraction of the drawn pixels there: how often lines break a flat-shaded colour.
double colour_steps(const Image& image, glm::vec2 centre, float radius) {
    std::size_t steps = 0, drawn = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x + 1 < image.width; ++x) {
            if (glm::distance(glm::vec2(x + 0.5f, y + 0.5f), centre) > radius || is_white(image.pixel(x, y))) continue;
            ++drawn;
            const glm::ivec4 d = glm::abs(glm::ivec4(image.pixel(x, y)) - glm::ivec4(image.pixel(x + 1, y)));
            steps += std::max({d.r, d.g, d.b}) > 8;
        }
    return drawn == 0 ? 0.0 : static_cast<double>(steps) / static_cast<double>(drawn);
}

// The refined cap around (0.3, 0.3, 0.9) faces the camera; the visible point towards (0.8, 0.55, 0.2)
// lies 0.9 from the sphere's centre (0.6 + one level-0 edge of transitions), on level-0 faces.
const glm::vec3 kCap = glm::normalize(glm::vec3(0.3f, 0.3f, 0.9f));
const glm::vec3 kCoarse = glm::normalize(glm::vec3(0.8f, 0.55f, 0.2f));

TEST_F(GoldenImage, RgbWireShowsTransitionsAroundTheCapAndDenserWiresInIt) {
    rgb::Mesh mesh = locally_refined_sphere();
    render::SurfaceGeometry geometry;
    geometry.rebuild(mesh);
    frame(geometry.bounds(mesh));
    const Image image = load("rgb_wire");
    ASSERT_EQ(glm::ivec2(image.width, image.height), kGoldenSize);
    const glm::vec2 centre = pixel_of(glm::vec3(0.0f));
    expect_inside_unit_sphere(image, centre, disc_radius(glm::vec3(0.0f), 1.0f));

    const render_test::PixelCounts counts = render_test::count_pixels(image);
    EXPECT_GT(counts.green, 500u);
    EXPECT_GT(counts.red, 100u);
    EXPECT_GT(counts.blue, 100u);
    // Red and blue faces are the transitions of the cap: their pixels gather around it.
    glm::dvec2 sum(0.0);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const render_test::PixelClass c = render_test::classify(image, x, y);
            if (c == render_test::PixelClass::Red || c == render_test::PixelClass::Blue) sum += glm::dvec2(x + 0.5, y + 0.5);
        }
    const glm::vec2 transitions(sum / static_cast<double>(counts.red + counts.blue));
    EXPECT_LT(glm::distance(transitions, pixel_of(kCap)), 0.6f * disc_radius(glm::vec3(0.0f), 1.0f));
    // Level 3 in the cap has 8 times as many edges per length as level 0: its triangles are a few
    // pixels across, where the wireframe fades (README). The dark wire of the coarse faces gives way
    // to faint lines there, which still break the cap's flat colour far more often.
    const float probe = 0.1f * disc_radius(glm::vec3(0.0f), 1.0f);
    const double coarse_wire = density(image, pixel_of(kCoarse), probe, is_wire);
    EXPECT_GT(coarse_wire, 0.05);
    EXPECT_LT(density(image, pixel_of(kCap), probe, is_wire), 0.5 * coarse_wire);
    EXPECT_GT(colour_steps(image, pixel_of(kCap), probe), 2.0 * colour_steps(image, pixel_of(kCoarse), probe));
}

TEST_F(GoldenImage, LevelLegendListsTheFourLevelsFinestFirst) {
    const Image image = load("level_legend");
    ASSERT_EQ(glm::ivec2(image.width, image.height), kGoldenSize);
    // The swatch column: one swatch per level, finest on top, level 0 blue at the bottom, each level's
    // colour differing from its neighbours'.
    const std::vector<render_test::Swatch> swatches = render_test::legend_column(image, 20, 12);
    ASSERT_EQ(swatches.size(), 4u) << "levels 0 to 3";
    EXPECT_EQ(swatches.back().kind, render_test::PixelClass::Blue);
    for (std::size_t i = 0; i + 1 < swatches.size(); ++i) EXPECT_NE(swatches[i].colour, swatches[i + 1].colour);
    const render_test::PixelClass finest = swatches.front().kind;
    ASSERT_NE(finest, render_test::PixelClass::Neutral) << "the top swatch has a clear hue";

    // The mesh shows the same colours: the cap in the top swatch's hue, far from it level 0's.
    rgb::Mesh mesh = locally_refined_sphere();
    render::SurfaceGeometry geometry;
    geometry.rebuild(mesh);
    frame(geometry.bounds(mesh));
    const float probe = 0.1f * disc_radius(glm::vec3(0.0f), 1.0f);
    const auto of_class = [](render_test::PixelClass c) { return [c](glm::u8vec4 p) { return render_test::classify(p) == c; }; };
    EXPECT_GT(density(image, pixel_of(kCap), probe, of_class(finest)), 0.8) << "the cap is at the finest level";
    EXPECT_GT(density(image, pixel_of(kCoarse), probe, of_class(render_test::PixelClass::Blue)), 0.8) << "far from it, level 0";
}

TEST_F(GoldenImage, LimitCageBrushShowsTheCageAroundTheSurfaceAndTheRingInTheBrush) {
    // The cage's vertices lie on the unit sphere and enclose the limit surface: the framing sphere.
    frame({glm::vec3(0.0f), 1.0f});
    const Image image = load("limit_cage_brush");
    ASSERT_EQ(glm::ivec2(image.width, image.height), kGoldenSize);
    expect_inside_unit_sphere(image, pixel_of(glm::vec3(0.0f)), disc_radius(glm::vec3(0.0f), 1.0f));
    // The limit surface lies strictly inside its control cage, so cage lines run against the background.
    std::size_t cage_against_background = 0;
    for (int y = 1; y + 1 < image.height; ++y)
        for (int x = 1; x + 1 < image.width; ++x)
            cage_against_background += is_dark(image.pixel(x, y)) && (is_white(image.pixel(x - 1, y)) || is_white(image.pixel(x + 1, y)) ||
                                                                      is_white(image.pixel(x, y - 1)) || is_white(image.pixel(x, y + 1)));
    EXPECT_GT(cage_against_background, 20u);
    // The brush ring is where the brush's sphere cuts the surface: inside the sphere's projection.
    const glm::vec3 brush(0.0f, 0.2f, 0.75f);
    std::size_t ring = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::u8vec4 p = image.pixel(x, y);
            if (!(p.r > 150 && p.r > p.g + 40 && p.g > p.b + 40)) continue;
            ++ring;
            EXPECT_LE(glm::distance(glm::vec2(x + 0.5f, y + 0.5f), pixel_of(brush)), disc_radius(brush, 0.25f) + 2.0f);
        }
    EXPECT_GT(ring, 30u);
}

}  // namespace
