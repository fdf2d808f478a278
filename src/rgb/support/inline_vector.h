#pragma once
// A vector with fixed inline capacity for the handful of faces and vertices one operator touches, so
// the hot paths of the operators never allocate. Elements are left unconstructed until pushed (the
// operators create many of these per split), hence the restriction to trivially copyable types.
#include <cstddef>
#include <initializer_list>
#include <new>
#include <span>
#include <stdexcept>
#include <type_traits>

namespace rgb {

template <class T, std::size_t N>
class InlineVector {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

public:
    InlineVector() {}
    InlineVector(std::initializer_list<T> items) {
        for (const T& t : items) push_back(t);
    }
    InlineVector(const InlineVector& o) : size_(o.size_) {
        for (std::size_t i = 0; i < size_; ++i) new (&storage_[i * sizeof(T)]) T(o[i]);
    }
    InlineVector& operator=(const InlineVector& o) {
        size_ = o.size_;
        for (std::size_t i = 0; i < size_; ++i) new (&storage_[i * sizeof(T)]) T(o[i]);
        return *this;
    }
    void push_back(const T& t) {
        if (size_ == N) throw std::length_error("InlineVector capacity exceeded");
        new (&storage_[size_ * sizeof(T)]) T(t);
        ++size_;
    }
    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    T* data() { return std::launder(reinterpret_cast<T*>(storage_)); }
    const T* data() const { return std::launder(reinterpret_cast<const T*>(storage_)); }
    T& operator[](std::size_t i) { return data()[i]; }
    const T& operator[](std::size_t i) const { return data()[i]; }
    T* begin() { return data(); }
    T* end() { return data() + size_; }
    const T* begin() const { return data(); }
    const T* end() const { return data() + size_; }
    operator std::span<const T>() const { return {data(), size_}; }

private:
    alignas(T) std::byte storage_[N * sizeof(T)];
    std::size_t size_ = 0;
};

}  // namespace rgb
