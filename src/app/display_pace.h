#pragma once
// How a frame's slice is shared between the queued work and the display catching up with what the
// work changed (Editor::update), so that both fit the slice together: the work stops early by what
// catching up is expected to cost, and the catching up goes in parts sized to the time left.
// The cost of catching up a changed face slot (with its share of the moved vertices: the geometry's
// update and the picking index's) varies with the mesh's size and the machine, so it is learned
// from the frames before, as is how many face slots the work changes in a frame.
#include <chrono>
#include <cstddef>

namespace app {

struct CatchUpTiming;

class DisplayPace {
public:
    // A catch-up too small to say much about the cost per slot is not learned from.
    static constexpr std::size_t kMinLearnedFaces = 256;

    // Learns from a frame's catching up.
    void caught_up(const CatchUpTiming& timing);
    // Learns from the face slots the work changed in a frame.
    void work_changed(std::size_t faces);
    // Expected microseconds to catch up `faces` changed face slots.
    double cost_us(std::size_t faces) const;
    // The most changed face slots caught up in `us` microseconds, expected.
    std::size_t faces_within(double us) const;
    // What the work leaves of `slice` for the display: time for `behind` slots already waiting and
    // for what the work changes in a frame (or `work_faces` if the work bounds its changes to that),
    // at most half the slice, so that the work goes on however far behind the display is.
    std::chrono::microseconds display_share(std::chrono::microseconds slice, std::size_t behind, std::size_t work_faces) const;

private:
    double us_per_face_ = 1.0;  // a first guess (a few hundred nanoseconds measured on a quiet machine)
    double faces_per_frame_ = 0.0;
};

}  // namespace app
