#pragma once
// A growing array of trivial values whose new elements are zero without being written: the memory
// comes from calloc, which hands out fresh pages (large blocks) untouched, so an array sized for a
// whole run costs nothing until used and another thread can fault it in ahead (Prefault). Elements
// are value-initialised by the allocation itself, so the array must only grow (a shrink followed by
// a growth would bring back old values).
#include <cstddef>
#include <cstdlib>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace rgb {

template <class T>
struct ZeroedAllocator {
    static_assert(std::is_trivially_copyable_v<T>);
    using value_type = T;

    ZeroedAllocator() = default;
    template <class U>
    explicit ZeroedAllocator(const ZeroedAllocator<U>&) {}

    T* allocate(std::size_t n) {
        if (void* p = std::calloc(n, sizeof(T))) return static_cast<T*>(p);
        throw std::bad_alloc();
    }
    void deallocate(T* p, std::size_t) { std::free(p); }
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
