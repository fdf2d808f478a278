#pragma once
// Progress and stop inside the long computations of `rgbsub remesh` (the cage, the fit, the detail),
// so that the editor's progress moves within each and its stop takes effect within a fraction of a
// second instead of at the next phase.
#include <algorithm>
#include <cstddef>
#include <functional>
#include <stdexcept>

namespace rgbdetail {

// Told the share of a computation done (0..1); returns false to stop it. A stopped computation
// throws Stopped and leaves its inputs as they were.
using ProgressFunction = std::function<bool(double)>;

struct Stopped : std::runtime_error {
    Stopped() : std::runtime_error("stopped") {}
};

// Tells progress (when there is one) the share done; throws Stopped when it says stop.
inline void report_share(const ProgressFunction& progress, double share) {
    if (progress && !progress(share)) throw Stopped();
}

// The progress of a part of a computation, from `from` to `to` of the whole (none without one).
// It refers to progress, which must outlive it.
inline ProgressFunction part_of(const ProgressFunction& progress, double from, double to) {
    if (!progress) return {};
    return [&progress, from, to](double share) { return progress(from + share * (to - from)); };
}

// body(begin, end) on consecutive chunks of [0, n), `chunk` elements each, telling progress the
// share done before each chunk and at the end: a long loop that reports as it goes and stops
// between chunks.
template <class Body>
void in_chunks(std::size_t n, std::size_t chunk, const ProgressFunction& progress, const Body& body) {
    for (std::size_t begin = 0; begin < n; begin += chunk) {
        report_share(progress, static_cast<double>(begin) / static_cast<double>(n));
        body(begin, std::min(n, begin + chunk));
    }
    report_share(progress, 1.0);
}

}  // namespace rgbdetail
