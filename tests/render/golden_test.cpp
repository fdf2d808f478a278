// Golden images: whole pictures a person has looked at, compared with a small per-pixel tolerance.
// RGBSUB_UPDATE_GOLDEN=1 rewrites them (target render_golden_update); review them before committing.
// Under CI (CI=true) the variable makes the test fail instead: CI must never bless its own pictures.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <string>
#include <string_view>

#include "render/headless.h"
#include "rgb/mesh.h"
#include "rgb/refine.h"
#include "test_meshes.h"

namespace {

using render::Image;
using render::RenderOptions;

// Per channel, out of 255: absorbs rounding differences between llvmpipe builds, far below any
// change of colour, shading or geometry a person would notice.
constexpr int kTolerance = 2;

struct GoldenCase {
    std::string name;
    std::function<rgb::Mesh()> mesh;
    RenderOptions options;
    friend void PrintTo(const GoldenCase& c, std::ostream* out) { *out << c.name; }
};

rgb::Mesh locally_refined_sphere() {
    rgb::Mesh mesh = render_test::icosphere(1);
    rgb::set_level(mesh, rgb::Region::sphere({0.3, 0.3, 0.9}, 0.6), 3);
    return mesh;
}

rgb::Mesh refined_icosahedron() {
    rgb::Mesh mesh = render_test::icosphere(0);
    rgb::refine_uniform(mesh, 2);
    return mesh;
}

RenderOptions rgb_wire() {
    RenderOptions o;
    o.shading = render::Shading::Flat;
    o.colouring = render::Colouring::RgbType;
    o.wireframe = true;
    return o;
}

RenderOptions level_map() {
    RenderOptions o;
    o.colouring = render::Colouring::Level;
    return o;
}

RenderOptions limit_with_cage_and_brush() {
    RenderOptions o;
    o.positions = render::PositionSource::Limit;
    o.base_mesh_overlay = true;
    o.brush = render::BrushCursor{{0.0f, 0.2f, 0.75f}, 0.25f};
    return o;
}

class Golden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, MatchesTheReviewedImage) {
    const GoldenCase& c = GetParam();
    rgb::Mesh mesh = c.mesh();
    const Image image = render::render_headless(mesh, c.options, {{256, 256}, 30.0f, 20.0f});
    const std::filesystem::path path = std::filesystem::path(RGBSUB_GOLDEN_DIR) / (c.name + ".png");
    if (std::getenv("RGBSUB_UPDATE_GOLDEN") != nullptr) {
        const char* ci = std::getenv("CI");
        ASSERT_FALSE(ci != nullptr && std::string_view(ci) == "true")
            << "RGBSUB_UPDATE_GOLDEN is set under CI=true: golden images are only rewritten by a person, who "
               "reviews them";
        render::write_png(image, path);
        std::cout << "wrote " << path << '\n';
        return;
    }
    const Image golden = render::read_png(path);
    ASSERT_EQ(golden.width, image.width);
    ASSERT_EQ(golden.height, image.height);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < image.rgba.size(); ++i)
        differing += std::abs(int{image.rgba[i]} - int{golden.rgba[i]}) > kTolerance;
    EXPECT_EQ(differing, 0u) << "channels differ by more than " << kTolerance << " from " << path;
}

INSTANTIATE_TEST_SUITE_P(Images, Golden,
                         ::testing::Values(GoldenCase{"rgb_wire", locally_refined_sphere, rgb_wire()},
                                           GoldenCase{"level_legend", locally_refined_sphere, level_map()},
                                           GoldenCase{"limit_cage_brush", refined_icosahedron, limit_with_cage_and_brush()}),
                         [](const auto& info) { return info.param.name; });

}  // namespace
