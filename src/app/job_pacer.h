#pragma once
// How much of each frame the queued work gets. A fixed slice starves the work when frames are slow
// (drawing millions of triangles in software takes longer than any fixed slice) and stutters the
// display when they are fast; instead the work gets what is left of a 60 Hz frame after drawing, but
// never less than drawing takes, so it keeps at least half of the time however slow frames are.
#include <chrono>

namespace app {

class JobPacer {
public:
    static constexpr double kFrameMs = 1000.0 / 60.0;
    static constexpr double kMinSliceMs = 4.0;
    static constexpr double kMaxSliceMs = 500.0;

    // The time the last frame spent on everything but the work (input, picking, drawing).
    void frame_drawn(double other_ms);
    std::chrono::microseconds slice() const;
    // The slice for frames that spend `other_ms` on everything else.
    static double slice_ms(double other_ms);

private:
    double other_ms_ = 0.0;  // smoothed over a few frames
    bool measured_ = false;
};

}  // namespace app
