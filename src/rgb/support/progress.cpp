#include "rgb/support/progress.h"

#include <algorithm>
#include <cmath>

namespace rgb {

void Progress::reach(double fraction) {
    fraction = std::clamp(fraction, 0.0, 1.0);
    double seen = fraction_.load(std::memory_order_relaxed);
    while (fraction > seen && !fraction_.compare_exchange_weak(seen, fraction, std::memory_order_relaxed)) {
    }
    if (!listener_ || fraction <= seen) return;
    // Only a report that passes another thousandth (or reaches the end) reaches the listener.
    if (std::floor(fraction * 1000.0) == std::floor(seen * 1000.0) && fraction < 1.0) return;
    const std::lock_guard<std::mutex> lock(listener_mutex_);
    // Another thread may have told a larger value meanwhile: tell the largest there is now.
    const double now = fraction_.load(std::memory_order_relaxed);
    if (now <= told_) return;
    told_ = now;
    listener_(now);
}

}  // namespace rgb
