#pragma once
// floor(2 log2 v) of a positive finite double, exactly: the half octave a criterion value falls in
// (the LOD driver's bands). std::log2 may round across a half octave's edge, and a library call per
// value costs more than the rest of a key. From the binary exponent, and whether the significand
// reaches sqrt(1/2): for a normal value an integer comparison of its bits with those of the least
// double above sqrt(1/2); for a subnormal one the sign of the fused multiply-add m^2 - 1/2 (never
// zero, sqrt(1/2) being irrational).
#include <bit>
#include <cmath>
#include <cstdint>

namespace rgb {

inline long half_octave(double value) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(value);
    if (const long biased_exponent = static_cast<long>(bits >> 52); biased_exponent > 0) {
        constexpr std::uint64_t kSignificand = (std::uint64_t(1) << 52) - 1;
        constexpr std::uint64_t kAboveRootHalf = 0x6A09E667F3BCDull;  // of 0x1.6A09E667F3BCDp-1
        return 2 * (biased_exponent - 1023) + ((bits & kSignificand) >= kAboveRootHalf ? 1 : 0);
    }
    int exponent = 0;
    const double m = std::frexp(value, &exponent);  // value = m 2^exponent, 1/2 <= m < 1
    return 2L * (exponent - 1) + (std::fma(m, m, -0.5) > 0.0 ? 1 : 0);
}

}  // namespace rgb
