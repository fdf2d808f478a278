#pragma once
// The first write to a page the process has not touched costs a page fault (the kernel finds and
// zeroes a page): 2.5 to 6 us a 4 KiB page on the build machines, a sixth of a budget run's time. On
// the current one the first access to the page from user code costs about 5 us more (prefault.cpp).
// A bulk refinement knows how much memory it is about to fill; it asks for those pages, and reads
// them once, on another core while it works, front to back as it will write them.
#include <atomic>
#include <cstddef>
#include <span>
#include <thread>
#include <vector>

namespace rgb {

class Prefault {
public:
    // Starts faulting in and reading the whole pages inside `ranges` on a thread of its own, all
    // ranges advancing together (their owners fill them side by side). Does nothing where the
    // platform cannot (no such call, or no thread to spare). The ranges must stay mapped while this
    // object lives: their owner destroys it before it frees or moves them.
    explicit Prefault(std::vector<std::span<std::byte>> ranges);
    // Stops at the next step (within about half a millisecond) and joins.
    ~Prefault();
    Prefault(const Prefault&) = delete;
    Prefault& operator=(const Prefault&) = delete;

private:
    void run(std::vector<std::span<std::byte>> ranges);

    std::atomic<bool> stop_{false};
    std::thread thread_;
};

}  // namespace rgb
