// The heat map of the distance to the dense mesh (Colouring::DetailDistance) on a cage with detail,
// headless: every face shows the colour of the band (colour_map.h) of its distance to the dense
// surface, computed here by brute force from the detail's points and the face's corners, lit as the
// plain colour is at the same pixel; the legend shows the bands' colours, the farthest on top; a mesh
// without detail shows the plain colour.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "gl_test_support.h"
#include "render/colour_map.h"
#include "render/headless.h"
#include "render/surface_geometry.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/surface_error.h"
#include "test_meshes.h"
#include "support/set_level.h"

namespace {

using render::Colouring;
using render::HeadlessView;
using render::Image;
using render::RenderOptions;

RenderOptions flat(Colouring colouring) {
    RenderOptions options;
    options.shading = render::Shading::Flat;
    options.colouring = colouring;
    options.legend = false;
    return options;
}

// A byte of a colour in [0, 1] lit by the factor that turned the plain colour into `plain_red`.
double lit(float colour, int plain_red) { return colour * plain_red / render::kPlainColour.r; }

TEST(DistanceHeatMap, EachFaceShowsTheColourOfItsDistancesBand) {
    rgb::Mesh mesh = render_test::bumpy_cage(0, 4);
    rgbtest::set_level(mesh, 3, rgb::Sphere{{0.2, -0.1, 1.0}, 0.8});
    const HeadlessView view{{480, 480}, 0.0f, 0.0f};  // seen from +z
    const Image heat = render::render_headless(mesh, flat(Colouring::DetailDistance), view);
    const Image plain = render::render_headless(mesh, flat(Colouring::Plain), view);

    render::SurfaceGeometry geometry;
    geometry.rebuild(mesh);
    const render::OrbitCamera camera = render::framing_camera(geometry.bounds(mesh), view);
    const glm::mat4 view_projection = camera.view_projection(1.0f);
    const auto to_pixels = [&](const glm::dvec3& p) {
        const glm::vec4 clip = view_projection * glm::vec4(glm::vec3(p), 1.0f);
        return glm::dvec2((glm::vec2(clip) / clip.w + 1.0f) * 0.5f * glm::vec2(view.size));
    };
    const double diagonal = rgb::bounding_box_diagonal(mesh.base());
    std::size_t checked = 0;
    std::set<int> bands_checked;
    for (rgb::FaceId f : mesh.faces()) {
        const std::array<glm::dvec3, 3> corners = geometry.corners(f);
        const glm::dvec3 normal = glm::normalize(glm::cross(corners[1] - corners[0], corners[2] - corners[0]));
        if (normal.z < 0.5) continue;  // turned away, or seen too obliquely to be hit squarely
        std::array<glm::dvec2, 3> screen;
        for (std::size_t c = 0; c < 3; ++c) screen[c] = to_pixels(corners[c]);
        const glm::dvec2 centre = (screen[0] + screen[1] + screen[2]) / 3.0;
        // Only faces whose centre is at least 3 pixels from each of their edges.
        bool roomy = true;
        for (std::size_t c = 0; c < 3; ++c) {
            const glm::dvec2 a = screen[c], b = screen[(c + 1) % 3];
            const glm::dvec2 d = b - a;
            roomy = roomy && std::abs(d.x * (centre.y - a.y) - d.y * (centre.x - a.x)) / glm::length(d) >= 3.0;
        }
        if (!roomy) continue;
        const int x = static_cast<int>(centre.x), y = view.size.y - 1 - static_cast<int>(centre.y);  // image rows from the top
        const int band = render::distance_band(render_test::brute_force_detail_distance(mesh, f) / diagonal);
        const glm::vec3 expected = render::distance_colour(band);
        const glm::u8vec4 shown = heat.pixel(x, y);
        const int plain_red = plain.pixel(x, y).r;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(shown[c], lit(expected[c], plain_red), 2.0) << "face slot " << f.idx << ", band " << band << ", channel " << c;
        ++checked;
        bands_checked.insert(band);
    }
    EXPECT_GT(checked, 40u);
    EXPECT_GE(bands_checked.size(), 4u) << "faces of several bands are seen";
}

TEST(DistanceHeatMap, LegendShowsEveryBandsColourFarthestOnTop) {
    rgb::Mesh mesh = render_test::bumpy_cage(0, 3);
    RenderOptions options;
    options.colouring = Colouring::DetailDistance;
    const Image image = render::render_headless(mesh, options, HeadlessView{{640, 480}, 0.0f, 0.0f});
    // Column 20 runs through the swatches (12 to 28 pixels from the left), left of the sphere.
    const std::vector<render_test::Swatch> legend = render_test::legend_column(image, 20, 12);
    ASSERT_EQ(legend.size(), static_cast<std::size_t>(render::kDistanceBands));
    for (int band = 0; band < render::kDistanceBands; ++band) {
        const glm::vec3 colour = render::distance_colour(band);
        const glm::u8vec4 swatch = legend[static_cast<std::size_t>(render::kDistanceBands - 1 - band)].colour;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(swatch[c], std::round(255.0f * colour[c]), 1.0) << "band " << band << ", channel " << c;
    }
}

TEST(DistanceHeatMap, AMeshWithoutDetailShowsThePlainColour) {
    rgb::Mesh mesh = render_test::icosphere(2);
    const HeadlessView view{{160, 120}, 30.0f, 20.0f};
    RenderOptions distance;
    distance.colouring = Colouring::DetailDistance;
    EXPECT_EQ(render::render_headless(mesh, distance, view).rgba, render::render_headless(mesh, RenderOptions{}, view).rgba)
        << "no legend either";
}

}  // namespace
