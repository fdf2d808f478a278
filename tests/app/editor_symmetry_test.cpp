// Symmetric painting: a stroke with the brush mirrored across x = 0 of the mesh's frame paints the
// mirror image too (the default cat is symmetric about x = 0: as much detail on each side, though RGB
// transitions may take the other diagonal there), is saved as `dab ... mirror x` lines and replays to
// the same mesh.
#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/editor.h"
#include "editor_fixture.h"
#include "io/mesh_file.h"
#include "io/script/lod_script.h"
#include "rgb/mesh/mesh.h"
#include "support/same_mesh.h"

namespace app {
namespace {

using test::kViewport;

// The refined faces on each side of x = 0, by level.
struct RefinedSides {
    std::array<int, rgb::kMaxLevel + 1> positive{}, negative{};
};

RefinedSides refined_sides(const rgb::Mesh& mesh) {
    RefinedSides sides;
    for (rgb::FaceId f : mesh.faces()) {
        if (mesh.level(f) == 0) continue;
        double x = 0.0;
        for (int i = 0; i < 3; ++i) x += mesh.insertion_position(mesh.from_vertex(rgb::Mesh::halfedge(f, i))).x;
        if (x != 0.0) ++(x > 0.0 ? sides.positive : sides.negative)[static_cast<std::size_t>(mesh.level(f))];
    }
    return sides;
}

// Each level's counts on the two sides within 10% of each other.
bool balanced(const RefinedSides& sides) {
    for (std::size_t level = 1; level < sides.positive.size(); ++level)
        if (std::abs(sides.positive[level] - sides.negative[level]) > std::max(sides.positive[level], sides.negative[level]) / 10)
            return false;
    return true;
}

class EditorSymmetry : public test::EditorFixture {
protected:
    void SetUp() override {
        ASSERT_TRUE(editor.open(test::asset_path("default.obj"))) << editor.message();
        editor.brush().target_level = 3;
        editor.brush().radius_px = 30.0f;
    }
    void paint_right_cheek() { stroke({0.55f * kViewport.x, 0.55f * kViewport.y}, {0.65f * kViewport.x, 0.5f * kViewport.y}, 12); }
};

TEST_F(EditorSymmetry, WithoutMirrorOneSideIsPainted) {
    paint_right_cheek();
    const RefinedSides sides = refined_sides(editor.document().mesh());
    EXPECT_GT(sides.positive[3], 0);
    EXPECT_FALSE(balanced(sides));
}

TEST_F(EditorSymmetry, MirrorXPaintsTheMirrorImageAndReplaysFromItsScript) {
    editor.brush().mirror = rgbio::kMirrorX;
    paint_right_cheek();
    const rgb::Mesh& painted = editor.document().mesh();
    const RefinedSides sides = refined_sides(painted);
    ASSERT_GT(sides.positive[3], 0);
    EXPECT_TRUE(balanced(sides)) << "level 3: " << sides.positive[3] << " faces at x > 0, " << sides.negative[3] << " at x < 0";
    EXPECT_EQ(editor.document().history().undo_steps(), 1u) << "one stroke, one undo step";

    const std::filesystem::path script = test::fresh_folder("symmetry_script") / "session.lod";
    ASSERT_TRUE(editor.save_strokes(script.string())) << editor.message();
    EXPECT_FALSE(editor.message_is_error()) << editor.message();
    std::stringstream text;
    text << std::ifstream(script).rdbuf();
    EXPECT_NE(text.str().find(" mirror x\n"), std::string::npos) << text.str();
    rgb::Mesh replayed = rgbio::load_mesh(test::asset_path("default.obj"));
    rgbio::ScriptRunner runner;
    for (const rgbio::ScriptLine& line : rgbio::parse_lod_script(text.str(), "session")) runner.run(replayed, line);
    EXPECT_TRUE(rgbtest::same_mesh(replayed, painted));
}

TEST(DabMirrorImages, ComeInTheOrderOfThePlanesCrossedAndReadBack) {
    rgb::Dab dab;
    dab.centre = {1.0, 2.0, 3.0};
    dab.view = glm::dvec3(-1.0, 0.5, 0.25);
    const std::vector<rgb::Dab> images = rgbio::with_mirror_images(dab, rgbio::kMirrorX | rgbio::kMirrorZ);
    ASSERT_EQ(images.size(), 4u);
    EXPECT_EQ(images[0].centre, glm::dvec3(1.0, 2.0, 3.0));
    EXPECT_EQ(images[1].centre, glm::dvec3(-1.0, 2.0, 3.0));
    EXPECT_EQ(images[2].centre, glm::dvec3(1.0, 2.0, -3.0));
    EXPECT_EQ(images[3].centre, glm::dvec3(-1.0, 2.0, -3.0));
    EXPECT_EQ(*images[3].view, glm::dvec3(1.0, 0.5, -0.25));

    const std::vector<rgbio::ScriptLine> lines =
        rgbio::parse_lod_script("brush set 2 0.1\ndab 1 2 3 mirror zx\ndab 1 2 3 0 0 -1 mirror y\n", "mirror");
    EXPECT_EQ(std::get<rgbio::DabEdit>(lines[1].edit).mirror, rgbio::kMirrorX | rgbio::kMirrorZ);
    EXPECT_EQ(rgbio::format_dab_line(std::get<rgbio::DabEdit>(lines[1].edit)), "dab 1 2 3 mirror xz");
    EXPECT_EQ(std::get<rgbio::DabEdit>(lines[2].edit).mirror, rgbio::kMirrorY);
    EXPECT_THROW(rgbio::parse_lod_script("brush set 2 0.1\ndab 1 2 3 mirror xx\n", "mirror"), std::exception);
    EXPECT_THROW(rgbio::parse_lod_script("brush set 2 0.1\ndab 1 2 3 mirror w\n", "mirror"), std::exception);
}

}  // namespace
}  // namespace app
