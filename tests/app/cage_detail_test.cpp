// The editor on a cage with detail (docs/detail.md): automatic LOD spends its budget where the surface
// departs most from the dense mesh, as a script's `budget` line does (and by edge length on a plain
// mesh, as before); the distance heat map's data (each face's distance band) follows edits and undo
// as a rebuild gives it.
#include <chrono>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "app/auto_lod.h"
#include "app/editor.h"
#include "editor_fixture.h"
#include "io/mesh_file.h"
#include "io/script/lod_script.h"
#include "render/surface_geometry.h"
#include "rgb/lod/limit_error.h"
#include "rgb/lod/lod_criteria.h"
#include "rgb/lod/lod_driver.h"
#include "rgb/values/surface_error.h"
#include "support/same_mesh.h"
#include "test_meshes.h"

namespace app {
namespace {

rgb::Mesh after_job(rgb::Mesh mesh, const AutoLodSettings& settings) {
    AutoLodJob job(mesh, settings);
    while (job.step(std::chrono::milliseconds(1))) {
    }
    return mesh;
}

rgb::Mesh after_driver(rgb::Mesh mesh, rgb::LodSettings settings) {
    rgb::LodDriver driver(mesh, std::move(settings));
    driver.run();
    return mesh;
}

rgb::Mesh after_script(rgb::Mesh mesh, const std::string& script) {
    rgbio::ScriptRunner runner;
    for (const rgbio::ScriptLine& line : rgbio::parse_lod_script(script, "budget.txt")) runner.run(mesh, line);
    return mesh;
}

TEST(CageAutoLod, SpendsTheBudgetWhereTheSurfaceDepartsMostFromTheDenseMesh) {
    const rgb::Mesh cage = render_test::bumpy_cage(1, 4);
    AutoLodSettings settings;
    settings.triangle_budget = 2000;
    settings.max_distance_fraction = 0.0;
    const rgb::Mesh unbounded = after_job(cage, settings);
    EXPECT_TRUE(rgbtest::same_mesh(unbounded, after_script(cage, "budget 2000\n"))) << "a script's budget has no threshold";
    EXPECT_LE(unbounded.num_faces(), 2000u);
    EXPECT_GT(unbounded.num_faces(), 1900u);
    rgb::LodSettings by_length;
    by_length.max_triangles = 2000;
    EXPECT_FALSE(rgbtest::same_mesh(unbounded, after_driver(cage, by_length))) << "not by edge length";

    // The threshold, a share of the size: the core's run with it, which stops short of the budget where
    // every split left gains less.
    settings.max_distance_fraction = 2e-3;
    const rgb::Mesh thresholded = after_job(cage, settings);
    rgb::LodSettings by_distance;
    by_distance.value = rgb::on_mesh(rgb::detail_error_value(cage.shared_base()));
    by_distance.threshold = 2e-3 * rgb::bounding_box_diagonal(cage.base());
    by_distance.max_triangles = 2000;
    EXPECT_TRUE(rgbtest::same_mesh(thresholded, after_driver(cage, by_distance)));
    EXPECT_LT(thresholded.num_faces(), unbounded.num_faces());
}

TEST(CageAutoLod, APlainMeshIsStillRefinedByEdgeLength) {
    const rgb::Mesh sphere = render_test::icosphere(1);
    const AutoLodSettings settings;  // the defaults: a budget of 100,000 and edges of 1% of the size
    rgb::LodSettings by_length;
    by_length.threshold = settings.max_edge_fraction * rgb::bounding_box_diagonal(sphere.base());
    by_length.max_triangles = settings.triangle_budget;
    const rgb::Mesh refined = after_job(sphere, settings);
    EXPECT_TRUE(rgbtest::same_mesh(refined, after_driver(sphere, by_length)));
    EXPECT_GT(refined.num_faces(), sphere.num_faces());
}

// What the document shows equals a rebuild with the distance bands, after a whole-mesh edit and its undo.
TEST(CageHeatMap, DistanceBandsFollowEditsAndUndoAsARebuild) {
    const std::filesystem::path file = std::filesystem::path(::testing::TempDir()) / "bumpy_cage.obj";
    rgbio::save_mesh(render_test::bumpy_cage(0, 4), file.string());
    Editor editor(test::kViewport);
    ASSERT_TRUE(editor.open(file.string())) << editor.message();
    ASSERT_NE(editor.document().mesh().base().detail(), nullptr) << "the saved state keeps the detail";
    editor.document().set_detail_distance(true);
    const auto expect_rebuild = [&] {
        const render::SurfaceGeometry& shown = editor.document().geometry();
        ASSERT_TRUE(shown.distance_scale());
        render::SurfaceGeometry fresh;
        fresh.set_detail_distance(true);
        fresh.rebuild(editor.document().mesh());
        ASSERT_EQ(shown.vertices().size(), fresh.vertices().size());
        for (std::size_t i = 0; i < fresh.vertices().size(); ++i) ASSERT_EQ(shown.vertices()[i], fresh.vertices()[i]) << "vertex " << i;
    };
    expect_rebuild();
    editor.start_flood_fill(3);
    editor.finish_work();
    expect_rebuild();
    ASSERT_TRUE(editor.undo());
    editor.finish_work();
    expect_rebuild();
    std::size_t coded = 0;
    for (const render::SurfaceVertex& v : editor.document().geometry().vertices()) coded += (v.code >> render::kCodeDistanceShift) != 0;
    EXPECT_GT(coded, 0u) << "the cage's faces are far from the dense surface";
}

}  // namespace
}  // namespace app
