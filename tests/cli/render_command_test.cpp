// `rgbsub render`: --size, --view and --mode change the picture as their descriptions say. The
// checks are properties a wrong picture breaks: image size, where the mesh covers the image seen
// face-on and edge-on, how many colours flat and smooth shading give, which colours each mode shows.
#include <algorithm>
#include <cmath>
#include <string>

#include <glm/common.hpp>
#include <glm/vec4.hpp>

#include "cli/commands.h"
#include "command_test_support.h"
#include "gl_test_support.h"
#include "obj_test_support.h"
#include "render/colour_map.h"
#include "render/image.h"

namespace cli {
namespace {

using render_test::PixelClass;

// A 2 x 2 square in the plane z = 0, facing +z.
const std::string kSquare = "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4\n";

class RenderCommand : public test::CommandFolder {
protected:
    render::Image render(const std::string& input, const std::vector<std::string>& options) {
        std::vector<std::string> args{"render", input, "-o", path("out.png")};
        args.insert(args.end(), options.begin(), options.end());
        const test::CommandRun run = test::run_command(args);
        EXPECT_EQ(run.exit_code, 0) << run.err;
        return render::read_image(path("out.png"));
    }
    // The octahedron refined to level 4 in a sphere of radius 0.6 around its +x corner: five levels
    // and all three colours (`rgbsub info` counts 280 green, 68 red and 12 blue triangles).
    std::string locally_refined() {
        const std::string input = write("octahedron.obj", rgbio::test::kOctahedron);
        EXPECT_EQ(test::run_command({"refine", input, "-o", path("local.obj"), "--level", "4", "--sphere", "1,0,0,0.6"}).exit_code, 0);
        return path("local.obj");
    }
};

std::size_t covered(const render::Image& image) {
    return image.width * image.height - render_test::count_pixels(image).background;
}

// Pairs of horizontally adjacent mesh pixels whose colours differ by more than `step` in a channel.
std::size_t jumps(const render::Image& image, int step) {
    std::size_t count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x + 1 < image.width; ++x) {
            if (render_test::classify(image, x, y) == PixelClass::Background ||
                render_test::classify(image, x + 1, y) == PixelClass::Background)
                continue;
            const glm::ivec4 d = glm::abs(glm::ivec4(image.pixel(x, y)) - glm::ivec4(image.pixel(x + 1, y)));
            count += std::max({d.r, d.g, d.b}) > step;
        }
    return count;
}

TEST_F(RenderCommand, SizeSetsTheImageSize) {
    const render::Image image = render(write("square.obj", kSquare), {"--size", "64x48"});
    EXPECT_EQ(image.width, 64);
    EXPECT_EQ(image.height, 48);
    const render::Image tall = render(path("square.obj"), {"--size", "30x70"});
    EXPECT_EQ(tall.width, 30);
    EXPECT_EQ(tall.height, 70);
}

// Azimuth 0 and elevation 0 look from +z: the square faces the camera and fills a good part of the
// view. From +x (azimuth 90) or from above (elevation 90) it is seen edge-on: at most a line.
TEST_F(RenderCommand, ViewSetsTheCameraAngles) {
    const std::string square = write("square.obj", kSquare);
    const std::size_t pixels = 100 * 100;
    const render::Image front = render(square, {"--size", "100x100", "--view", "0,0"});
    EXPECT_GT(covered(front), pixels / 4);
    EXPECT_NE(render_test::classify(front, 50, 50), PixelClass::Background) << "the centre of the square";
    EXPECT_LT(covered(render(square, {"--size", "100x100", "--view", "90,0"})), pixels / 50);
    EXPECT_LT(covered(render(square, {"--size", "100x100", "--view", "0,90"})), pixels / 50);
    const render::Image slanted = render(square, {"--size", "100x100", "--view", "60,0"});
    EXPECT_LT(covered(slanted), covered(front)) << "turned by 60 degrees the square looks narrower";
    EXPECT_GT(covered(slanted), pixels / 50);
}

// Flat shading lights each face by its own normal, so brightness jumps where two faces meet (the
// octahedron's faces differ by 70 degrees); smooth shading interpolates shared vertex normals, so
// brightness changes gradually everywhere, edges included.
TEST_F(RenderCommand, FlatModeShowsTheEdgesAndShadedModeHidesThem) {
    const std::string octahedron = write("octahedron.obj", rgbio::test::kOctahedron);
    constexpr int kJump = 30;  // of 255; neighbouring pixels on one smooth surface differ far less
    EXPECT_GT(jumps(render(octahedron, {"--size", "160x120", "--mode", "flat"}), kJump), 40u) << "the visible edges";
    EXPECT_EQ(jumps(render(octahedron, {"--size", "160x120", "--mode", "shaded"}), kJump), 0u);
    EXPECT_EQ(jumps(render(octahedron, {"--size", "160x120"}), kJump), 0u) << "shaded is the default";
}

TEST_F(RenderCommand, ModesShowTheirColours) {
    const std::string mesh = locally_refined();
    const std::vector<std::string> view{"--size", "200x150", "--view", "60,20"};
    const auto counts = [&](const std::string& mode) {
        std::vector<std::string> options = view;
        options.insert(options.end(), {"--mode", mode});
        return render_test::count_pixels(render(mesh, options));
    };
    // Plain grey: no pixel shows one channel clearly above the others.
    const render_test::PixelCounts shaded = counts("shaded");
    EXPECT_EQ(shaded.green + shaded.red + shaded.blue, 0u);
    EXPECT_GT(shaded.neutral, 200u * 150u / 10);
    // Triangle types: the untouched faces are green, the transition faces red and blue.
    const render_test::PixelCounts rgb = counts("rgb");
    EXPECT_GT(rgb.green, 100u);
    EXPECT_GT(rgb.red, 100u);
    EXPECT_GT(rgb.blue, 100u);
    // One fixed colour per level: level 0 blue, the finer levels other hues (README).
    const render_test::PixelCounts level = counts("level");
    EXPECT_GT(level.blue, 100u);
    EXPECT_GT(level.green + level.red, 100u);
}

// --mode distance on a cage made by remesh: the cage's flat triangles far from the dense mesh (the
// farthest bands: red), the same refined to the detail's level on it (the nearest band: blue), the
// legend's swatches in the bands' colours beside them; a mesh without detail is refused, saying why.
TEST_F(RenderCommand, DistanceModeShowsACagesDistanceToItsDenseMesh) {
    const std::string octahedron = write("octahedron.obj", rgbio::test::kOctahedron);
    ASSERT_EQ(test::run_command({"refine", octahedron, "-o", path("dense.obj"), "--level", "3", "--plain"}).exit_code, 0);
    ASSERT_EQ(test::run_command({"remesh", path("dense.obj"), "-o", path("cage.obj"), "--cage-triangles", "8"}).exit_code, 0);
    // To the detail's finest level: the faces' levels are 3 and 4 here (Σ3 has M's 512 triangles overall;
    // the faces over which M is denser take 4), and every displayed triangle is then on M.
    ASSERT_EQ(test::run_command({"refine", path("cage.obj"), "-o", path("on_dense.obj"), "--level", "4"}).exit_code, 0);
    const std::vector<std::string> options{"--size", "640x480", "--mode", "distance"};
    // The colours of the mesh's upper half, above the legend in the bottom-left corner.
    const auto upper_half = [](const render::Image& image) {
        const auto half = static_cast<std::ptrdiff_t>(image.rgba.size() / 2);
        return render_test::count_pixels(render::Image{image.width, image.height / 2, {image.rgba.begin(), image.rgba.begin() + half}});
    };

    const render::Image cage = render(path("cage.obj"), options);
    const std::vector<render_test::Swatch> legend = render_test::legend_column(cage, 20, 12);
    ASSERT_EQ(legend.size(), static_cast<std::size_t>(render::kDistanceBands));
    for (int band = 0; band < render::kDistanceBands; ++band) {
        const glm::vec3 colour = render::distance_colour(band);
        const glm::u8vec4 swatch = legend[static_cast<std::size_t>(render::kDistanceBands - 1 - band)].colour;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(swatch[c], std::round(255.0f * colour[c]), 1.0) << "band " << band;
    }
    const render_test::PixelCounts far = upper_half(cage);
    EXPECT_GT(far.red, 5000u);
    EXPECT_EQ(far.blue, 0u);
    const render_test::PixelCounts near = upper_half(render(path("on_dense.obj"), options));
    EXPECT_EQ(near.red, 0u);
    EXPECT_GT(near.blue, 5000u);

    const test::CommandRun refused = test::run_command({"render", octahedron, "-o", path("plain.png"), "--mode", "distance"});
    EXPECT_EQ(refused.exit_code, exit_bad_input);
    EXPECT_NE(refused.err.find("--mode distance needs a cage with detail"), std::string::npos) << refused.err;
}

}  // namespace
}  // namespace cli
