#pragma once
// Triangles compared up to rotation but not reflection: the orientation is part of the identity of a
// face, so two faces with the same vertices in opposite order are different.
#include <algorithm>
#include <array>

namespace rgbtest {

// Rotates the triangle so that its smallest element comes first, keeping the cyclic order.
template <class T>
std::array<T, 3> canonical_rotation(const std::array<T, 3>& t) {
    const auto first = static_cast<std::size_t>(std::min_element(t.begin(), t.end()) - t.begin());
    return {t[first], t[(first + 1) % 3], t[(first + 2) % 3]};
}

}  // namespace rgbtest
