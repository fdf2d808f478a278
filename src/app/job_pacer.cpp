#include "app/job_pacer.h"

#include <algorithm>

namespace app {

void JobPacer::frame_drawn(double other_ms) {
    other_ms_ = measured_ ? 0.7 * other_ms_ + 0.3 * other_ms : other_ms;
    measured_ = true;
}

double JobPacer::slice_ms(double other_ms) {
    return std::clamp(std::max(kFrameMs - other_ms, other_ms), kMinSliceMs, kMaxSliceMs);
}

std::chrono::microseconds JobPacer::slice() const {
    return std::chrono::microseconds(static_cast<long long>(1000.0 * slice_ms(other_ms_)));
}

}  // namespace app
