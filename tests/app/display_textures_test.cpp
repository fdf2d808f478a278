// Opening a file reads its materials' diffuse textures for the texture mode (file_appearance.h):
// each used texture once, as a layer; a texture that is missing or unreadable is a warning naming
// it, and its faces are marked for the checker; the rest of the file loads either way.
#include <algorithm>
#include <fstream>

#include <gtest/gtest.h>

#include "app/loaded_document.h"
#include "textured_quad.h"

namespace app {
namespace {

std::filesystem::path folder(const std::string& name) { return std::filesystem::path(::testing::TempDir()) / name; }

// The warnings that mention `text`.
std::size_t mentioning(const std::vector<std::string>& warnings, const std::string& text) {
    return static_cast<std::size_t>(std::ranges::count_if(warnings, [&](const std::string& w) { return w.find(text) != std::string::npos; }));
}

TEST(DisplayTextures, AReadableTextureIsALayerOfItsFaces) {
    const LoadedDocument loaded = load_document(test::write_textured_quad(folder("texture_ok")).string(), render::PositionSource::Displayed);
    EXPECT_EQ(mentioning(loaded.warnings, "texture"), 0u);
    const auto& look = loaded.geometry.appearance();
    ASSERT_NE(look, nullptr);
    EXPECT_EQ(look->face_textures, (std::vector<std::uint32_t>{0, 0}));
    ASSERT_EQ(look->textures.count(), 1u);
    EXPECT_EQ(look->textures.width, test::kHalvesSide);
    EXPECT_EQ(look->textures.height, test::kHalvesSide);
    // Texel (x, 0): red in the left half, blue in the right one (textured_quad.h).
    for (int x = 0; x < test::kHalvesSide; ++x) {
        const bool left = x < test::kHalvesSide / 2;
        EXPECT_EQ(look->textures.rgba[4 * x], left ? 255 : 0) << "texel " << x;
        EXPECT_EQ(look->textures.rgba[4 * x + 2], left ? 0 : 255) << "texel " << x;
    }
    // The display draws the texture on both faces.
    for (const render::AppearanceVertex& corner : loaded.geometry.appearance_vertices()) EXPECT_EQ(corner.texture, 0u);
}

TEST(DisplayTextures, AMissingTextureIsAWarningNamingItAndItsFacesShowTheChecker) {
    const LoadedDocument loaded = load_document(test::write_textured_quad(folder("texture_gone"), "gone.png").string(), render::PositionSource::Displayed);
    EXPECT_EQ(mentioning(loaded.warnings, "gone.png' of material 'skin' cannot be shown (there is no such file); its faces show the texture checker"), 1u)
        << testing::PrintToString(loaded.warnings);
    const auto& look = loaded.geometry.appearance();
    ASSERT_NE(look, nullptr);
    EXPECT_EQ(look->face_textures, (std::vector<std::uint32_t>(2, render::kUnreadableTexture)));
    EXPECT_EQ(look->textures.count(), 0u);
    EXPECT_EQ(loaded.mesh.num_faces(), 2u) << "the mesh loads anyway";
}

TEST(DisplayTextures, AnUnreadableTextureIsAWarningWithStbsReason) {
    const std::filesystem::path quad = test::write_textured_quad(folder("texture_broken"), "broken.png");
    std::ofstream(quad.parent_path() / "broken.png") << "not an image";
    const LoadedDocument loaded = load_document(quad.string(), render::PositionSource::Displayed);
    EXPECT_EQ(mentioning(loaded.warnings, "broken.png' of material 'skin' cannot be shown ("), 1u) << testing::PrintToString(loaded.warnings);
    EXPECT_EQ(mentioning(loaded.warnings, "cannot read the image: unknown image type"), 1u) << testing::PrintToString(loaded.warnings);
    EXPECT_EQ(loaded.geometry.appearance()->face_textures, (std::vector<std::uint32_t>(2, render::kUnreadableTexture)));
}

}  // namespace
}  // namespace app
