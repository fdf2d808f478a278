#pragma once
// The first write to a page the process has not touched costs a page fault (the kernel finds and
// zeroes a page): 2.5 to 6 us a 4 KiB page on the build machines, a sixth of a budget run's time. On
// a virtual machine the first access to that page may cost as much again, the host's own fault
// (prefault.cpp). A bulk refinement knows how much memory it is about to fill; it asks for those
// pages, and touches them, on another core while it works, front to back as it will write them.
#include <atomic>
#include <cstddef>
#include <span>
#include <thread>
#include <vector>

namespace rgb {

class Prefault {
public:
    // Whether the thread also reads each page it faulted in (prefault.cpp). Only for ranges that stay
    // mapped while this object lives: their owner destroys it before it frees or moves them.
    enum class Touch { no, yes };
    // Starts faulting in the whole pages inside `ranges` on a thread of its own, all ranges advancing
    // together (their owners fill them side by side). Does nothing where the platform cannot (no
    // such call, or no thread to spare).
    explicit Prefault(std::vector<std::span<std::byte>> ranges, Touch touch = Touch::no);
    // Stops at the next step (within about 0.1 ms) and joins.
    ~Prefault();
    Prefault(const Prefault&) = delete;
    Prefault& operator=(const Prefault&) = delete;

private:
    void run(std::vector<std::span<std::byte>> ranges, Touch touch);

    std::atomic<bool> stop_{false};
    std::thread thread_;
};

}  // namespace rgb
