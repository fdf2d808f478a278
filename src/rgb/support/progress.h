#pragma once
// How far a long piece of work is (reading, restoring or writing a file of millions of triangles),
// as a fraction of the whole that only grows, so that a window can show it while another thread
// works. Cheap enough to leave on: the work reports every few thousand items, each report is an
// atomic add and a compare-exchange, and a listener is called only when the fraction passes another
// thousandth.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <utility>

namespace rgb {

class Progress {
public:
    // Told of the fraction each time it passes another thousandth, and of 1 at the end; calls are
    // serialised and their values increase, whichever thread reports.
    using Listener = std::function<void(double)>;
    explicit Progress(Listener listener = {}) : listener_(std::move(listener)) {}
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    // In [0, 1]; never decreases. Any thread.
    double fraction() const { return fraction_.load(std::memory_order_relaxed); }
    // The work is at least `fraction` of the way (clamped to [0, 1]). Any thread.
    void reach(double fraction);

private:
    std::atomic<double> fraction_{0.0};
    Listener listener_;
    std::mutex listener_mutex_;
    double told_ = -1.0;  // the last value the listener got, under listener_mutex_
};

// A part of the whole, [begin, end] of a Progress, handed to a step of the work, which may cut it
// into parts of its own. A default span reports nowhere, so code that reports costs nothing when
// nobody watches.
class ProgressSpan {
public:
    ProgressSpan() = default;
    explicit ProgressSpan(Progress* progress, double begin = 0.0, double end = 1.0) : progress_(progress), begin_(begin), end_(end) {}

    // The part from `from` to `to` of this span (fractions of it).
    ProgressSpan part(double from, double to) const { return ProgressSpan(progress_, at(from), at(to)); }
    // This span done up to `fraction` of it.
    void reach(double fraction) const {
        if (progress_) progress_->reach(at(fraction));
    }
    void done() const { reach(1.0); }
    bool watched() const { return progress_ != nullptr; }

private:
    double at(double fraction) const { return begin_ + (end_ - begin_) * fraction; }

    Progress* progress_ = nullptr;
    double begin_ = 0.0, end_ = 0.0;
};

// Counts `total` items of a span as they are done, from any number of threads: add() a batch of a
// few thousand at a time. More than `total` (an estimate was low) stops at the span's end.
class ProgressCounter {
public:
    ProgressCounter(ProgressSpan span, std::uint64_t total) : span_(span), total_(total) {}
    void add(std::uint64_t items) {
        if (!span_.watched() || total_ == 0) return;
        const std::uint64_t done = done_.fetch_add(items, std::memory_order_relaxed) + items;
        span_.reach(std::min(1.0, static_cast<double>(done) / static_cast<double>(total_)));
    }

private:
    ProgressSpan span_;
    std::uint64_t total_;
    std::atomic<std::uint64_t> done_{0};
};

}  // namespace rgb
