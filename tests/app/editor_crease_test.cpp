// The editor's crease tool scripted through its input layer, without X or GL (issue 13): on the
// machined part, a click on a base edge tags it, a drag tags the edges it passes, Shift untags, each
// release is one undo step, undo and redo restore the mesh bit for bit, and the tags survive saving.
#include <filesystem>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include "app/editor.h"
#include "editor_fixture.h"
#include "io/mesh_file.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/sharp_angle.h"
#include "rgb/values/loop_geometry.h"
#include "support/same_mesh.h"
#include "support/set_level.h"

namespace app {
namespace {

using test::kViewport;

class EditorCreases : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(editor.open(test::asset_path("machined_part.obj"))) << editor.message();
        editor.crease_tool().active = true;
    }

    const rgb::BaseMesh& base() { return editor.document().mesh().base(); }

    // Pixel of a world point (origin top left, y down, as the mouse reports it).
    glm::vec2 pixel_of(const glm::dvec3& p) const {
        const glm::mat4 vp = editor.camera().camera().view_projection(float(kViewport.x) / float(kViewport.y));
        const glm::vec4 clip = vp * glm::vec4(glm::vec3(p), 1.0f);
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        return {(ndc.x + 1.0f) * 0.5f * kViewport.x - 0.5f, (1.0f - ndc.y) * 0.5f * kViewport.y - 0.5f};
    }

    // Where the middle of a base edge is drawn: its level-1 vertex if the mesh has it, else the
    // midpoint of the drawn edge.
    glm::dvec3 drawn_middle(const BaseEdge& e) {
        const rgb::Mesh& mesh = editor.document().mesh();
        const glm::dvec3 middle = 0.5 * (base().position(e.first) + base().position(e.second));
        for (rgb::VertexId v : mesh.vertices())
            if (mesh.level(v) == 1 && glm::distance(mesh.base_space_position(v), middle) < 1e-12)
                return rgb::displayed_position(mesh, v);
        return middle;
    }
    glm::vec2 middle_of(const BaseEdge& e) { return pixel_of(drawn_middle(e)); }

    // Untagged flat interior base edges (cap diagonals and wall seams) whose drawn middle the cursor
    // hits where it is, i.e. the edge faces the camera unhidden.
    std::vector<BaseEdge> visible_flat_edges() {
        std::vector<BaseEdge> edges;
        for (std::uint32_t h = 0; h < 3 * base().num_faces(); ++h) {
            if (base().opposite(h) < h || rgb::dihedral_angle_degrees(base(), h) > 1e-9) continue;
            const std::uint32_t a = base().face(h / 3)[h % 3], b = base().to_vertex(h);
            const BaseEdge edge{std::min(a, b), std::max(a, b)};
            const glm::dvec3 middle = drawn_middle(edge);
            editor.mouse_moved(pixel_of(middle));
            const auto hit = editor.cursor_hit();
            if (hit && glm::distance(hit->point, middle) < 1e-3) edges.push_back(edge);
        }
        return edges;
    }

    void drag(glm::vec2 from, glm::vec2 to, Modifiers mods = {}) {
        editor.mouse_moved(from);
        editor.mouse_pressed(MouseButton::Left, mods);
        editor.mouse_moved(to);
        editor.mouse_released(MouseButton::Left);
    }

    int tag_of(const BaseEdge& e) {
        for (const rgb::EdgeSharpness& t : base().sharp_features().edges)
            if (t.a == e.first && t.b == e.second) return t.sharpness;
        return 0;
    }

    Editor editor{kViewport};
};

TEST_F(EditorCreases, ClickTagsTheEdgeUnderTheCursorAsOneUndoStep) {
    const std::vector<BaseEdge> edges = visible_flat_edges();
    ASSERT_GE(edges.size(), 2u) << "the framed part shows flat edges";
    const rgb::Mesh original = editor.document().mesh();
    drag(middle_of(edges[0]), middle_of(edges[0]));
    EXPECT_EQ(base().sharp_features().edges, (std::vector<rgb::EdgeSharpness>{{edges[0].first, edges[0].second, 10}}));
    EXPECT_EQ(editor.document().history().undo_steps(), 1u);
    EXPECT_EQ(editor.document().history().undo_label(), "tag 1 crease edge");
    EXPECT_TRUE(editor.document().dirty());

    // A click on it again changes nothing and leaves no step; Shift+click untags it.
    drag(middle_of(edges[0]), middle_of(edges[0]));
    EXPECT_EQ(editor.document().history().undo_steps(), 1u);
    drag(middle_of(edges[0]), middle_of(edges[0]), {.shift = true});
    EXPECT_TRUE(base().sharp_features().edges.empty());
    EXPECT_TRUE(rgbtest::same_mesh(editor.document().mesh(), original));

    ASSERT_TRUE(editor.undo());
    EXPECT_EQ(tag_of(edges[0]), 10);
    ASSERT_TRUE(editor.undo());
    EXPECT_TRUE(base().sharp_features().edges.empty());
    EXPECT_TRUE(rgbtest::same_mesh(editor.document().mesh(), original));
    ASSERT_TRUE(editor.redo());
    EXPECT_EQ(tag_of(edges[0]), 10);
}

TEST_F(EditorCreases, DragTagsTheEdgesItPassesAndTheRefinedSurfaceFollows) {
    editor.start_flood_fill(2);
    editor.finish_work();
    const rgb::Mesh refined = editor.document().mesh();
    const std::vector<BaseEdge> edges = visible_flat_edges();
    ASSERT_GE(edges.size(), 2u);
    drag(middle_of(edges.front()), middle_of(edges.back()));
    EXPECT_EQ(tag_of(edges.front()), 10);
    EXPECT_EQ(tag_of(edges.back()), 10);
    // Same vertices, new positions: the mesh is the level-2 mesh of the tagged part.
    EXPECT_EQ(editor.document().mesh().num_faces(), refined.num_faces());
    EXPECT_EQ(editor.document().mesh().num_vertices(), refined.num_vertices());
    rgb::Mesh direct(std::make_shared<const rgb::BaseMesh>(base().positions(), base().faces(), base().sharp_features()));
    rgbtest::set_level(direct, 2);
    EXPECT_TRUE(rgbtest::same_mesh(editor.document().mesh(), direct));

    const std::filesystem::path saved = std::filesystem::path(::testing::TempDir()) / "editor_creases_saved.obj";
    ASSERT_TRUE(editor.save_as(saved.string())) << editor.message();
    const rgb::Mesh reloaded = rgbio::load_mesh(saved.string());
    EXPECT_EQ(reloaded.base().sharp_features(), base().sharp_features());
    EXPECT_TRUE(rgbtest::same_mesh(reloaded, editor.document().mesh()));

    ASSERT_TRUE(editor.undo());
    EXPECT_TRUE(rgbtest::same_mesh(editor.document().mesh(), refined));
}

TEST_F(EditorCreases, WithTheToolOffTheLeftButtonPaintsLevels) {
    editor.crease_tool().active = false;
    editor.brush().unit = RadiusUnit::World;
    editor.brush().radius_world = 2.0f;
    const std::vector<BaseEdge> edges = visible_flat_edges();
    ASSERT_FALSE(edges.empty());
    drag(middle_of(edges.front()), middle_of(edges.front()));
    editor.finish_work();  // strokes are applied over frames
    EXPECT_TRUE(base().sharp_features().edges.empty());
    EXPECT_GT(editor.document().mesh().num_faces(), base().num_faces()) << "the brush refined instead";
}

TEST_F(EditorCreases, TaggingByAngleIsOneUndoStep) {
    ASSERT_TRUE(editor.set_sharp_features(with_edges_above(editor.document().mesh(), 30.0), "tag edges above 30 degrees"));
    EXPECT_EQ(base().sharp_features().edges.size(), 44u);
    EXPECT_EQ(editor.document().history().undo_steps(), 1u);
    ASSERT_TRUE(editor.undo());
    EXPECT_TRUE(base().sharp_features().edges.empty());
}

TEST_F(EditorCreases, EditsBeforeAndAfterARetagUndoAndRedoThroughIt) {
    // A retag keeps every slot, so the journal's steps on either side of it stay valid.
    const rgb::Mesh original = editor.document().mesh();
    editor.start_flood_fill(1);
    editor.finish_work();
    const rgb::Mesh level1 = editor.document().mesh();
    ASSERT_TRUE(editor.set_sharp_features(with_edges_above(level1, 30.0), "tag edges above 30 degrees"));
    editor.start_flood_fill(2);
    editor.finish_work();
    const rgb::Mesh tagged_level2 = editor.document().mesh();
    ASSERT_EQ(editor.document().history().undo_steps(), 3u);

    rgb::Mesh direct(std::make_shared<const rgb::BaseMesh>(base().positions(), base().faces(), base().sharp_features()));
    rgbtest::set_level(direct, 2);
    EXPECT_TRUE(rgbtest::same_mesh(tagged_level2, direct));

    ASSERT_TRUE(editor.undo());
    ASSERT_TRUE(editor.undo());
    EXPECT_TRUE(base().sharp_features().edges.empty());
    EXPECT_TRUE(rgbtest::same_mesh(editor.document().mesh(), level1));
    ASSERT_TRUE(editor.undo());
    EXPECT_TRUE(rgbtest::same_mesh(editor.document().mesh(), original));
    for (int i = 0; i < 3; ++i) ASSERT_TRUE(editor.redo());
    EXPECT_TRUE(rgbtest::same_mesh(editor.document().mesh(), tagged_level2));
}

}  // namespace
}  // namespace app
