// How a frame's slice is shared between the work and the display (display_pace.h): the display's
// share follows the cost per changed face slot it learns and the slots waiting, and never takes more
// than half of the slice.
#include <chrono>

#include <gtest/gtest.h>

#include "app/display_pace.h"
#include "app/document.h"

namespace app {
namespace {

// A pace that has seen many catch-ups costing `us_per_face` microseconds a slot (smoothing forgets
// the first guess geometrically).
DisplayPace learned(double us_per_face) {
    DisplayPace pace;
    CatchUpTiming timing;
    timing.faces = 4000;
    timing.geometry_ms = 0.75 * us_per_face * 4.0;
    timing.index_ms = 0.25 * us_per_face * 4.0;
    for (int i = 0; i < 100; ++i) pace.caught_up(timing);
    return pace;
}

TEST(DisplayPace, LearnsTheCostPerChangedSlot) {
    const DisplayPace pace = learned(2.0);
    EXPECT_NEAR(pace.cost_us(1000), 2000.0, 1.0);
    EXPECT_NEAR(static_cast<double>(pace.faces_within(2000.0)), 1000.0, 1.0);
    EXPECT_EQ(pace.faces_within(-5.0), 0u);
}

TEST(DisplayPace, IgnoresCatchUpsTooSmallToMeasure) {
    DisplayPace pace = learned(2.0);
    CatchUpTiming tiny;
    tiny.faces = DisplayPace::kMinLearnedFaces - 1;
    tiny.geometry_ms = 50.0;  // a frame the thread waited in: 200 us a slot
    pace.caught_up(tiny);
    EXPECT_NEAR(pace.cost_us(1000), 2000.0, 1.0);
}

TEST(DisplayPace, TheDisplaysShareCoversWhatWaitsAndWhatTheWorkMakesUpToHalfTheSlice) {
    using std::chrono::microseconds;
    DisplayPace pace = learned(2.0);
    const microseconds slice(12000);
    EXPECT_EQ(pace.display_share(slice, 0, 0), microseconds(0)) << "no work changed anything yet";
    EXPECT_NEAR(static_cast<double>(pace.display_share(slice, 1000, 0).count()), 2000.0, 2.0);
    EXPECT_NEAR(static_cast<double>(pace.display_share(slice, 1000, 500).count()), 3000.0, 2.0) << "a job that bounds its changes";
    for (int i = 0; i < 100; ++i) pace.work_changed(1500);
    EXPECT_NEAR(static_cast<double>(pace.display_share(slice, 0, 0).count()), 3000.0, 2.0) << "what the work changes a frame";
    EXPECT_EQ(pace.display_share(slice, 1000000, 0), microseconds(6000)) << "the work keeps half however far behind";
}

}  // namespace
}  // namespace app
