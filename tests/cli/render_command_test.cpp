// `rgbsub render`: --size, --view and --mode change the picture as their descriptions say. The
// checks are properties a wrong picture breaks: image size, where the mesh covers the image seen
// face-on and edge-on, how many colours flat and smooth shading give, which colours each mode shows.
#include <algorithm>
#include <string>

#include <glm/common.hpp>
#include <glm/vec4.hpp>

#include "command_test_support.h"
#include "gl_test_support.h"
#include "obj_test_support.h"
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

}  // namespace
}  // namespace cli
