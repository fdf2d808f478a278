#include "rgb/support/prefault.h"

#include <algorithm>
#include <cstdint>
#include <system_error>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace rgb {

namespace {

constexpr std::uintptr_t kPage = 4096;
// Pages per call: small enough that a stop request is heard soon, large enough that the calls cost
// little next to the faults.
constexpr std::uintptr_t kStep = 64 * kPage;

// Faults in the pages of [begin, end) (page-aligned) for writing; false where the system cannot.
bool populate(std::uintptr_t begin, std::uintptr_t end) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
    return ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE) == 0;
#else
    (void)begin;
    (void)end;
    return false;
#endif
}

// Reads a byte of each page of [begin, end). On the build machine, a virtual one, the first access
// to a page from user code costs about 5 us more, a fault the guest kernel never sees (populating
// the page, or reading it from the kernel, does not spare it): made here, on this thread, it is not
// the writer's. A read, since the owner may be writing the page already (the value is dropped, so a
// write that races it changes nothing). Unlike populating, which fails on memory gone, a read of
// memory unmapped meanwhile would crash: hence the owner keeps the ranges (prefault.h).
void read_pages(std::uintptr_t begin, std::uintptr_t end) {
    for (std::uintptr_t page = begin; page < end; page += kPage) (void)*reinterpret_cast<const volatile std::byte*>(page);
}

}  // namespace

Prefault::Prefault(std::vector<std::span<std::byte>> ranges) {
    std::erase_if(ranges, [](std::span<std::byte> r) { return r.size() < kStep; });
    if (ranges.empty()) return;
    try {
        thread_ = std::thread([this, ranges = std::move(ranges)] { run(ranges); });
    } catch (const std::system_error&) {
        // No thread: the pages fault in as they are written, as without this.
    }
}

Prefault::~Prefault() {
    stop_.store(true, std::memory_order_relaxed);
    if (thread_.joinable()) thread_.join();
}

void Prefault::run(std::vector<std::span<std::byte>> ranges) {
    struct Front {
        std::uintptr_t next, end, share;
    };
    std::vector<Front> fronts;
    std::uintptr_t largest = 0;
    for (std::span<std::byte> r : ranges) {
        // Whole pages only: a partial page at either end may hold other data, which could be faulted
        // in as well but is not worth a call.
        const auto begin = reinterpret_cast<std::uintptr_t>(r.data());
        const Front f{(begin + kPage - 1) & ~(kPage - 1), (begin + r.size()) & ~(kPage - 1), 0};
        if (f.end <= f.next) continue;
        fronts.push_back(f);
        largest = std::max(largest, f.end - f.next);
    }
    // Each round takes a share of every range in proportion to its size, so that all fronts keep pace
    // with arrays that fill in step (faces and their neighbours, vertices and their positions).
    for (Front& f : fronts) f.share = std::max(kPage, (f.end - f.next) / (largest / kStep + 1) & ~(kPage - 1));
    for (bool left = true; left && !stop_.load(std::memory_order_relaxed);) {
        left = false;
        for (Front& f : fronts) {
            if (f.next >= f.end) continue;
            const std::uintptr_t to = std::min(f.end, f.next + f.share);
            if (!populate(f.next, to)) return;
            read_pages(f.next, to);
            f.next = to;
            left = true;
        }
    }
}

}  // namespace rgb
