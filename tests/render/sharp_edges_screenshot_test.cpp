// Creases on screen (issue 13): the machined part (assets/machined_part.obj) with its edges above 30
// degrees tagged stays a sharp-edged block at level 3, and its creases are drawn as coloured lines.
//
// With every rim and corner edge infinitely sharp, each face of the part is a flat region bounded by
// straight creases that end at corners, so the tagged part's Loop surface is the polyhedron itself
// (docs/loop-creases.md: a crease is the B-spline of its polyline, a flat region stays flat). Seen by
// one camera, the level-3 surface must cover the pixels the base mesh covers, while the untagged
// part's rounded edges and corners cover visibly fewer.
#include <gtest/gtest.h>

#include "render/headless.h"
#include "render/offscreen_context.h"
#include "rgb/lod/refine.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/sharp_angle.h"
#include "support/obj_reader.h"

namespace {

using render::Image;
using render::RenderOptions;

constexpr render::HeadlessView kView{{400, 300}, 35.0f, 30.0f};

std::shared_ptr<const rgb::BaseMesh> machined_part(bool tagged) {
    const rgbtest::TestMesh part = rgbtest::read_obj(RGBSUB_ASSETS_DIR "/machined_part.obj");
    const rgb::BaseMesh plain(part.positions, part.triangles);
    rgb::SharpFeatures features;
    if (tagged) features.edges = rgb::edges_sharper_than(plain, 30.0);
    return std::make_shared<const rgb::BaseMesh>(part.positions, part.triangles, features);
}

// Every image framed on the base mesh, so that the three surfaces are seen by the same camera.
Image render_at_level(bool tagged, int level, const RenderOptions& options) {
    rgb::Mesh mesh(machined_part(tagged));
    rgb::refine_uniform(mesh, level);
    render::OffscreenContext context(kView.size.x, kView.size.y);
    render::Renderer renderer;
    renderer.attach(mesh);
    std::vector<glm::vec3> corners;
    for (const glm::dvec3& p : mesh.base().positions()) corners.emplace_back(p);
    renderer.draw(render::framing_camera(render::bounding_sphere(corners), kView), options, kView.size);
    return context.read_pixels();
}

std::size_t covered(const Image& image) {
    std::size_t n = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) n += image.pixel(x, y) != glm::u8vec4(255, 255, 255, 255);
    return n;
}

std::size_t magenta(const Image& image) {
    std::size_t n = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::u8vec4 p = image.pixel(x, y);
            n += p.r > 150 && p.b > 80 && p.g + 60 < p.b;
        }
    return n;
}

TEST(SharpEdgesOnScreen, TaggedMachinedPartStaysABlockAtLevelThree) {
    RenderOptions surface_only;
    surface_only.sharp_edges = false;
    const std::size_t block = covered(render_at_level(true, 0, surface_only));
    const std::size_t sharp = covered(render_at_level(true, 3, surface_only));
    const std::size_t smooth = covered(render_at_level(false, 3, surface_only));
    ASSERT_GT(block, 400u * 300u / 10) << "the part fills a good part of the view";
    // The same polyhedron, triangulated 64 times finer: equal up to rounding along the outline.
    EXPECT_NEAR(static_cast<double>(sharp), static_cast<double>(block), 0.002 * static_cast<double>(block));
    // Loop without tags rounds every edge and shrinks the part.
    EXPECT_LT(static_cast<double>(smooth), 0.93 * static_cast<double>(block));
}

TEST(SharpEdgesOnScreen, CreasesAreDrawnAsColouredLinesOnlyWhereTagged) {
    const RenderOptions options;  // sharp edges shown by default
    EXPECT_GT(magenta(render_at_level(true, 3, options)), 300u) << "44 crease edges, several pixels each";
    EXPECT_EQ(magenta(render_at_level(false, 3, options)), 0u);
    RenderOptions hidden;
    hidden.sharp_edges = false;
    EXPECT_EQ(magenta(render_at_level(true, 3, hidden)), 0u);
}

}  // namespace
