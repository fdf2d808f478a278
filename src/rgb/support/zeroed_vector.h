#pragma once
// A growing array of trivial values whose new elements are zero without being written: a large block
// is mapped fresh from the kernel (zero pages, untouched), so an array sized for a whole run costs
// nothing until used and another thread can fault it in ahead (Prefault); a small one comes from
// calloc. Mapping directly rather than through calloc keeps that true whatever malloc is told (a
// program may have it keep freed memory for reuse, when calloc would clear a reused block at once).
// Elements are value-initialised by the allocation itself, so the array must only grow (a shrink
// followed by a growth would bring back old values).
#include <cstddef>
#include <cstdlib>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#include <sys/mman.h>

namespace rgb {

template <class T>
struct ZeroedAllocator {
    static_assert(std::is_trivially_copyable_v<T>);
    using value_type = T;
#if defined(__SANITIZE_ADDRESS__)
    // AddressSanitizer checks only what comes through its allocator.
    static constexpr std::size_t kMappedBytes = static_cast<std::size_t>(-1);
#else
    static constexpr std::size_t kMappedBytes = std::size_t{1} << 20;
#endif
    static constexpr std::size_t kMaxItems = static_cast<std::size_t>(-1) / 2 / sizeof(T);

    ZeroedAllocator() = default;
    template <class U>
    explicit ZeroedAllocator(const ZeroedAllocator<U>&) {}

    T* allocate(std::size_t n) {
        if (n > kMaxItems) throw std::bad_alloc();
        if (n * sizeof(T) >= kMappedBytes) {
            void* p = ::mmap(nullptr, n * sizeof(T), PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
            if (p == MAP_FAILED) throw std::bad_alloc();
            return static_cast<T*>(p);
        }
        if (void* p = std::calloc(n, sizeof(T))) return static_cast<T*>(p);
        throw std::bad_alloc();
    }
    void deallocate(T* p, std::size_t n) {
        if (n * sizeof(T) >= kMappedBytes)
            ::munmap(p, n * sizeof(T));
        else
            std::free(p);
    }
    // Value-initialisation: the memory is zero already.
    template <class U>
    void construct(U*) {}
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
    template <class U>
    bool operator==(const ZeroedAllocator<U>&) const {
        return true;
    }
};

template <class T>
using ZeroedVector = std::vector<T, ZeroedAllocator<T>>;

}  // namespace rgb
