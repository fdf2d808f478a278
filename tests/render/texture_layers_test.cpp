// The materials' textures as layers of one array texture (render/texture_layers.h): rows turned
// bottom-up, as texture coordinate v counts; smaller images scaled to the largest size.
#include <gtest/gtest.h>

#include "render/texture_layers.h"

namespace {

// A width x height image whose every texel is `rgba`.
render::Image filled(int width, int height, std::array<std::uint8_t, 4> rgba) {
    render::Image image{width, height, std::vector<std::uint8_t>(4 * static_cast<std::size_t>(width * height))};
    for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = rgba[i % 4];
    return image;
}

TEST(TextureLayers, RowsBottomUpAndEveryLayerAtTheLargestSize) {
    // 4 x 2: top row red, bottom row blue (image rows run from the top).
    render::Image two_rows = filled(4, 2, {255, 0, 0, 255});
    for (int x = 0; x < 4; ++x) std::swap(two_rows.rgba[4 * (4 + x)], two_rows.rgba[4 * (4 + x) + 2]);
    const render::TextureLayers layers = render::texture_layers({two_rows, filled(2, 1, {0, 255, 0, 255})});
    EXPECT_EQ(layers.width, 4);
    EXPECT_EQ(layers.height, 2);
    ASSERT_EQ(layers.count(), 2u);
    for (int x = 0; x < 4; ++x) {
        EXPECT_EQ(layers.rgba[4 * x + 2], 255) << "layer 0's first row is the image's bottom one (blue), texel " << x;
        EXPECT_EQ(layers.rgba[4 * (4 + x)], 255) << "its second row the top one (red), texel " << x;
    }
    // A uniform image stays uniform when scaled.
    for (int i = 0; i < 8; ++i) EXPECT_EQ(layers.rgba[32 + 4 * i + 1], 255) << "layer 1, texel " << i;
}

// 5 layers of 64 x 32 take 40 KiB; within 8 KiB they are halved twice (32 x 16: 10 KiB), to 16 x 8.
TEST(TextureLayers, ManyLargeTexturesAreScaledDownToFitTheMemoryBound) {
    const render::Image large = filled(64, 32, {10, 20, 30, 255});
    const render::TextureLayers layers = render::texture_layers({large, large, large, large, large}, 8 << 10);
    EXPECT_EQ(layers.width, 16);
    EXPECT_EQ(layers.height, 8);
    EXPECT_EQ(layers.count(), 5u);
}

TEST(TextureLayers, NoImagesNoLayers) { EXPECT_EQ(render::texture_layers({}).count(), 0u); }

}  // namespace
