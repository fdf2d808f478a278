// The brush's pieces on their own: falloff targets, mode inversion, the hit mapped to base space,
// the work's share of a frame and stroke spacing (picking: surface_picking_test.cpp).
#include <array>
#include <chrono>
#include <vector>

#include <gtest/gtest.h>

#include "app/brush.h"
#include "app/job_pacer.h"
#include "app/stroke_sampler.h"
#include "rgb/mesh/mesh.h"

namespace app {
namespace {

TEST(BrushTarget, RefineTapersFromTheTargetToNothingAcrossTheFalloffBand) {
    // radius 1, falloff 0.5: full strength up to 0.5, then linear to 0 at the rim.
    EXPECT_EQ(rgb::dab_level_at(BrushMode::Refine, 4, 0.5f, 0.0, 1.0), 4);
    EXPECT_EQ(rgb::dab_level_at(BrushMode::Refine, 4, 0.5f, 0.5, 1.0), 4);
    EXPECT_EQ(rgb::dab_level_at(BrushMode::Refine, 4, 0.5f, 0.75, 1.0), 2);  // strength 1/2
    EXPECT_EQ(rgb::dab_level_at(BrushMode::Refine, 4, 0.5f, 1.0, 1.0), 0);
    EXPECT_EQ(rgb::dab_level_at(BrushMode::Refine, 4, 0.5f, 1.01, 1.0), -1);
}

TEST(BrushTarget, CoarsenTapersUpToTheFinestLevel) {
    EXPECT_EQ(rgb::dab_level_at(BrushMode::Coarsen, 0, 0.5f, 0.2, 1.0), 0);
    EXPECT_EQ(rgb::dab_level_at(BrushMode::Coarsen, 0, 0.5f, 0.75, 1.0), rgb::kMaxLevel / 2);
    EXPECT_EQ(rgb::dab_level_at(BrushMode::Coarsen, 0, 0.5f, 1.0, 1.0), rgb::kMaxLevel);
}

TEST(BrushTarget, SetLevelHoldsTheCoreAndLeavesTheBandAlone) {
    EXPECT_EQ(rgb::dab_level_at(BrushMode::Set, 2, 0.5f, 0.4, 1.0), 2);
    EXPECT_EQ(rgb::dab_level_at(BrushMode::Set, 2, 0.5f, 0.6, 1.0), -1);
    EXPECT_EQ(rgb::dab_level_at(BrushMode::Set, 2, 0.0f, 1.0, 1.0), 2);
}

TEST(BrushTarget, ShiftSwapsRefineAndCoarsen) {
    EXPECT_EQ(effective_mode(BrushMode::Refine, true), BrushMode::Coarsen);
    EXPECT_EQ(effective_mode(BrushMode::Coarsen, true), BrushMode::Refine);
    EXPECT_EQ(effective_mode(BrushMode::Set, true), BrushMode::Set);
    EXPECT_EQ(effective_mode(BrushMode::Refine, false), BrushMode::Refine);
}

// The hit maps to the point with the same barycentric coordinates in the face's base-space
// triangle; here the displayed triangle is the base one moved and scaled by 2, so the hit at
// d0 + 0.25 (d1 - d0) + 0.5 (d2 - d0) is b0 + 0.25 (b1 - b0) + 0.5 (b2 - b0), and radii halve.
TEST(BrushTarget, AHitMapsToBaseSpaceByItsBarycentricCoordinates) {
    const std::vector<glm::dvec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const std::vector<rgb::Triangle> t{{0, 1, 2}};
    const rgb::Mesh mesh(p, t);
    const std::array<glm::dvec3, 3> displayed{glm::dvec3(5, 5, 1), glm::dvec3(7, 5, 1), glm::dvec3(5, 7, 1)};
    const glm::dvec3 point = displayed[0] + 0.25 * (displayed[1] - displayed[0]) + 0.5 * (displayed[2] - displayed[0]);
    const BaseSpaceHit hit = to_base_space(mesh, rgb::FaceId(0), displayed, point, 0.4);
    EXPECT_NEAR(hit.centre.x, 0.25, 1e-12);
    EXPECT_NEAR(hit.centre.y, 0.5, 1e-12);
    EXPECT_EQ(hit.centre.z, 0.0);
    EXPECT_NEAR(hit.radius, 0.2, 1e-12);
}

// The work gets what drawing leaves of a 60 Hz frame, but never less than drawing takes.
TEST(JobPacer, TheWorksShareFollowsTheFrameTime) {
    EXPECT_DOUBLE_EQ(JobPacer::slice_ms(2.0), 1000.0 / 60.0 - 2.0);
    EXPECT_DOUBLE_EQ(JobPacer::slice_ms(12.0), 12.0);  // half of a slow frame
    EXPECT_DOUBLE_EQ(JobPacer::slice_ms(300.0), 300.0);
    EXPECT_DOUBLE_EQ(JobPacer::slice_ms(5000.0), JobPacer::kMaxSliceMs);
    JobPacer pacer;
    EXPECT_EQ(pacer.slice(), std::chrono::microseconds(16666));
    pacer.frame_drawn(200.0);
    EXPECT_EQ(pacer.slice(), std::chrono::microseconds(200000));
}

TEST(StrokeSampler, SpacesDabsEvenlyAcrossSamples) {
    StrokeSampler sampler;
    EXPECT_EQ(sampler.begin({0.0f, 0.0f}).size(), 1u);
    EXPECT_TRUE(sampler.move_to({3.0f, 0.0f}, 4.0f).empty());
    const std::vector<glm::vec2> dabs = sampler.move_to({17.0f, 0.0f}, 4.0f);
    ASSERT_EQ(dabs.size(), 4u);  // at 4, 8, 12, 16
    for (std::size_t i = 0; i < dabs.size(); ++i) EXPECT_FLOAT_EQ(dabs[i].x, 4.0f * static_cast<float>(i + 1));
    EXPECT_EQ(sampler.move_to({20.0f, 0.0f}, 4.0f).size(), 1u);  // the remainder carries over
}

}  // namespace
}  // namespace app
