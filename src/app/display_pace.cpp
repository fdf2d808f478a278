#include "app/display_pace.h"

#include <algorithm>

#include "app/document.h"

namespace app {

namespace {

// Smoothing over a few frames: a frame the thread waited for a core in should not halve the work of the next.
constexpr double kKeep = 0.7;

}  // namespace

void DisplayPace::caught_up(const CatchUpTiming& timing) {
    if (timing.faces < kMinLearnedFaces) return;
    const double us = 1000.0 * (timing.geometry_ms + timing.index_ms) / static_cast<double>(timing.faces);
    us_per_face_ = kKeep * us_per_face_ + (1.0 - kKeep) * us;
}

void DisplayPace::work_changed(std::size_t faces) { faces_per_frame_ = kKeep * faces_per_frame_ + (1.0 - kKeep) * static_cast<double>(faces); }

double DisplayPace::cost_us(std::size_t faces) const { return us_per_face_ * static_cast<double>(faces); }

std::size_t DisplayPace::faces_within(double us) const { return us <= 0.0 ? 0 : static_cast<std::size_t>(us / us_per_face_); }

std::chrono::microseconds DisplayPace::display_share(std::chrono::microseconds slice, std::size_t behind, std::size_t work_faces) const {
    const double work = work_faces != 0 ? static_cast<double>(work_faces) : faces_per_frame_;
    const double us = us_per_face_ * (static_cast<double>(behind) + work);
    return std::chrono::microseconds(static_cast<long long>(std::min(us, 0.5 * static_cast<double>(slice.count()))));
}

}  // namespace app
