// Detail by size or accuracy from the editor (app/detail_job.h): run a slice at a time it gives the
// command line's result, its script line replays to the same mesh, and a tolerance reports the error
// it reached; cancelled or cut short by the triangle limit it claims no script line.
#include <gtest/gtest.h>

#include <chrono>

#include "app/detail_job.h"
#include "io/script/detail_edit.h"
#include "io/script/lod_script.h"
#include "rgb/mesh/invariants.h"
#include "rgb/mesh/mesh.h"
#include "support/same_mesh.h"
#include "support/test_meshes.h"
#include "support/set_level.h"

namespace {

rgbio::DetailEdit edit_of(rgbio::DetailCriterion criterion, double percent) {
    rgbio::DetailEdit edit;
    edit.criterion = criterion;
    edit.amount = {percent, true};
    return edit;
}

int run_in_slices(app::DetailJob& job) {
    int frames = 1;
    while (job.step(std::chrono::microseconds(200))) ++frames;
    return frames;
}

TEST(DetailJob, InSlicesItGivesTheCommandLinesResultAndItsScriptLineReplaysIt) {
    const rgbtest::TestMesh base = rgbtest::bipyramid(7);
    for (const auto& [criterion, percent, line] : {std::tuple{rgbio::DetailCriterion::Tolerance, 0.2, "tolerance 0.2%\n"},
                                                   std::tuple{rgbio::DetailCriterion::MaxEdge, 4.0, "max-edge 4%\n"}}) {
        SCOPED_TRACE(line);
        rgb::Mesh mesh = rgbtest::make_rgb_mesh(base);
        rgbtest::set_level(mesh, 2);  // what the mesh held before does not matter
        app::DetailJob job(mesh, edit_of(criterion, percent), 1'000'000);
        EXPECT_GT(run_in_slices(job), 1);
        EXPECT_EQ(job.progress(), 1.0f);
        EXPECT_TRUE(job.changed());
        EXPECT_FALSE(job.budget_bound());
        EXPECT_TRUE(rgb::check_invariants(mesh).ok());

        rgb::Mesh whole = rgbtest::make_rgb_mesh(base);
        const rgbio::DetailOutcome outcome = rgbio::apply_detail_edit(whole, edit_of(criterion, percent), 1'000'000);
        EXPECT_TRUE(rgbtest::same_mesh(whole, mesh));
        EXPECT_EQ(job.reached_error(), outcome.reached_error);
        if (criterion == rgbio::DetailCriterion::Tolerance) {
            ASSERT_TRUE(job.reached_error().has_value());
            EXPECT_LE(*job.reached_error(), rgbio::world_amount(mesh, {percent, true}));
        }

        ASSERT_EQ(job.script(), std::optional<std::string>(line));
        rgb::Mesh replayed = rgbtest::make_rgb_mesh(base);
        rgbio::ScriptRunner runner;
        for (const rgbio::ScriptLine& l : rgbio::parse_lod_script(*job.script(), "session")) runner.run(replayed, l);
        EXPECT_TRUE(rgbtest::same_mesh(replayed, mesh));
    }
}

TEST(DetailJob, CancelledOrCutShortItClaimsNoScriptLine) {
    const rgbtest::TestMesh base = rgbtest::bipyramid(7);
    rgb::Mesh mesh = rgbtest::make_rgb_mesh(base);
    app::DetailJob cancelled(mesh, edit_of(rgbio::DetailCriterion::Tolerance, 0.05), 1'000'000);
    EXPECT_TRUE(cancelled.step(std::chrono::microseconds(0)));
    cancelled.cancel();
    EXPECT_FALSE(cancelled.step(std::chrono::seconds(1)));
    EXPECT_FALSE(cancelled.script().has_value());
    EXPECT_TRUE(rgb::check_invariants(mesh).ok());

    rgb::Mesh small = rgbtest::make_rgb_mesh(base);
    app::DetailJob bound(small, edit_of(rgbio::DetailCriterion::Tolerance, 0.05), 500);
    run_in_slices(bound);
    EXPECT_TRUE(bound.budget_bound());
    EXPECT_LE(small.num_faces(), 500u);
    EXPECT_FALSE(bound.script().has_value());
}

}  // namespace
