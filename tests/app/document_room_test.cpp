// The document keeps room ahead of the mesh, so that no edit copies its arrays part way (a copy of
// the mesh and its display in one frame took 0.9 s at 3.8M triangles): observed as the storage of
// the mesh's faces and of the displayed triangles staying where it is while an edit runs.
#include <gtest/gtest.h>

#include "app/document.h"
#include "editor_fixture.h"
#include "render/surface_geometry.h"
#include "rgb/lod/refine.h"
#include "rgb/lod/requests.h"
#include "support/set_level.h"

namespace app {
namespace {

struct ArrayStorage {
    const void* faces;
    const void* triangles;
    bool operator==(const ArrayStorage&) const = default;
};

ArrayStorage storage_of(Document& document) {
    return {&document.mesh().face_vertices(rgb::FaceId(0)), document.geometry().vertices().data()};
}

// A bunny refined after it was read, as a benchmark or a job leaves it: its arrays hold exactly
// its triangles, no more.
LoadedDocument bunny_at_level_2() {
    LoadedDocument loaded = load_document(test::asset_path("bunny.obj"), render::PositionSource::Displayed);
    rgb::refine_uniform(loaded.mesh, 2);
    loaded.geometry.rebuild(loaded.mesh);
    loaded.index.rebuild(loaded.mesh, loaded.geometry);
    return loaded;
}

// Refines the ball around the first vertex of face 0 one level deeper, as one edit.
void refine_around_first_corner(Document& document, double radius) {
    const glm::dvec3 centre = document.mesh().insertion_position(document.mesh().face_vertices(rgb::FaceId(0))[0]);
    document.begin_edit("refine");
    const rgb::RequestStats stats = rgbtest::set_level(document.mesh(), 3, rgb::Sphere{centre, radius});
    document.end_edit(stats.splits > 0);
}

TEST(DocumentRoom, AnAdoptedMeshHasRoomForTwiceItsTriangles) {
    Document document;
    document.adopt(bunny_at_level_2(), "bunny.obj");
    const std::size_t faces = document.mesh().num_faces();
    ASSERT_EQ(faces, 58784u);  // 3674 * 4^2
    const ArrayStorage before = storage_of(document);
    // About a third of the surface one level deeper.
    refine_around_first_corner(document, 0.5 * document.geometry().bounds(document.mesh()).radius);
    ASSERT_GT(document.mesh().num_faces(), faces + faces / 4) << "the edit must grow the mesh past what any vector would hold spare";
    ASSERT_LT(document.mesh().num_faces(), 2 * faces);
    EXPECT_EQ(storage_of(document), before);
}

TEST(DocumentRoom, AnEditStartsWithRoomForAQuarterMoreThanThereAre) {
    Document document;
    document.adopt(bunny_at_level_2(), "bunny.obj");
    // Everything one level deeper: four times the triangles, past the room kept at adoption.
    document.begin_edit("set all");
    rgbtest::set_level(document.mesh(), 3);
    document.end_edit(true);
    const std::size_t faces = document.mesh().num_faces();
    ASSERT_EQ(faces, 235136u);
    // The next edit moves the storage as it begins, before it changes anything, if it must; not while it runs.
    document.begin_edit("refine");
    const ArrayStorage begun = storage_of(document);
    const glm::dvec3 centre = document.mesh().insertion_position(document.mesh().face_vertices(rgb::FaceId(0))[0]);
    rgbtest::set_level(document.mesh(), 4, rgb::Sphere{centre, 0.25 * document.geometry().bounds(document.mesh()).radius});
    document.end_edit(true);
    ASSERT_GT(document.mesh().num_faces(), faces + faces / 20);
    ASSERT_LE(document.mesh().num_faces(), faces + faces / 4);
    EXPECT_EQ(storage_of(document), begun);
}

TEST(DocumentRoom, AWholeMeshJobReservesForTwiceItsEstimate) {
    Editor editor(test::kViewport);
    ASSERT_TRUE(editor.open(test::asset_path("bunny.obj")));
    editor.start_flood_fill(2);  // 3674 -> 58,784 triangles
    editor.finish_work();
    ASSERT_EQ(editor.document().mesh().num_faces(), 58784u);
    const ArrayStorage before = storage_of(editor.document());
    // A second edit as large as a quarter of the mesh and more: a set over part of the surface.
    Document& document = editor.document();
    refine_around_first_corner(document, 0.5 * document.geometry().bounds(document.mesh()).radius);
    ASSERT_GT(document.mesh().num_faces(), 58784u + 58784u / 4);
    ASSERT_LT(document.mesh().num_faces(), 2 * 58784u);
    EXPECT_EQ(storage_of(document), before);
}

}  // namespace
}  // namespace app
