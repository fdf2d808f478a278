// Timing helpers the frame benchmarks share (brush_bench, criteria_bench, frame_bench).
#pragma once

#include <algorithm>
#include <cstddef>
#include <ctime>
#include <vector>

namespace bench {

// This thread's processor time in milliseconds: on a machine shared with other work a frame's wall
// time also counts the time the thread waited for a core.
inline double thread_cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

// The value at share p (0: the least, 0.5: the median, 1: the largest) of v, by rank; 0 for none.
inline double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(p * static_cast<double>(v.size() - 1))];
}

}  // namespace bench
