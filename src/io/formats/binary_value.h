#pragma once
// One value of a binary file's bytes (which need not be aligned), as a double.
#include <cstring>

namespace rgbio {

template <class T>
double binary_value(const unsigned char* bytes) {
    T value;
    std::memcpy(&value, bytes, sizeof value);
    return static_cast<double>(value);
}

}  // namespace rgbio
