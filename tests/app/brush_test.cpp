// The brush's pieces on their own: falloff targets, mode inversion and stroke spacing.
#include <vector>

#include <gtest/gtest.h>

#include "app/brush.h"
#include "app/stroke_sampler.h"

namespace app {
namespace {

TEST(BrushTarget, RefineTapersFromTheTargetToNothingAcrossTheFalloffBand) {
    // radius 1, falloff 0.5: full strength up to 0.5, then linear to 0 at the rim.
    EXPECT_EQ(target_at_distance(BrushMode::Refine, 4, 0.5f, 0.0, 1.0), 4);
    EXPECT_EQ(target_at_distance(BrushMode::Refine, 4, 0.5f, 0.5, 1.0), 4);
    EXPECT_EQ(target_at_distance(BrushMode::Refine, 4, 0.5f, 0.75, 1.0), 2);  // strength 1/2
    EXPECT_EQ(target_at_distance(BrushMode::Refine, 4, 0.5f, 1.0, 1.0), 0);
    EXPECT_EQ(target_at_distance(BrushMode::Refine, 4, 0.5f, 1.01, 1.0), -1);
}

TEST(BrushTarget, CoarsenTapersUpToTheFinestLevel) {
    EXPECT_EQ(target_at_distance(BrushMode::Coarsen, 0, 0.5f, 0.2, 1.0), 0);
    EXPECT_EQ(target_at_distance(BrushMode::Coarsen, 0, 0.5f, 0.75, 1.0), kMaxBrushLevel / 2);
    EXPECT_EQ(target_at_distance(BrushMode::Coarsen, 0, 0.5f, 1.0, 1.0), kMaxBrushLevel);
}

TEST(BrushTarget, SetLevelHoldsTheCoreAndLeavesTheBandAlone) {
    EXPECT_EQ(target_at_distance(BrushMode::SetLevel, 2, 0.5f, 0.4, 1.0), 2);
    EXPECT_EQ(target_at_distance(BrushMode::SetLevel, 2, 0.5f, 0.6, 1.0), -1);
    EXPECT_EQ(target_at_distance(BrushMode::SetLevel, 2, 0.0f, 1.0, 1.0), 2);
}

TEST(BrushTarget, ShiftSwapsRefineAndCoarsen) {
    EXPECT_EQ(effective_mode(BrushMode::Refine, true), BrushMode::Coarsen);
    EXPECT_EQ(effective_mode(BrushMode::Coarsen, true), BrushMode::Refine);
    EXPECT_EQ(effective_mode(BrushMode::SetLevel, true), BrushMode::SetLevel);
    EXPECT_EQ(effective_mode(BrushMode::Refine, false), BrushMode::Refine);
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
