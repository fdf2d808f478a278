// half_octave against exact integer arithmetic: for v = M 2^E (M an integer below 2^53),
// floor(2 log2 v) = floor(log2 v^2) = (bit width of M^2) - 1 + 2E, with M^2 held exactly in two words.
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "rgb/lod/half_octave.h"

namespace rgbtest {
namespace {

long exact_half_octave(double v) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(v);
    const long biased = static_cast<long>(bits >> 52);
    const std::uint64_t fraction = bits & ((std::uint64_t(1) << 52) - 1);
    const std::uint64_t m = biased > 0 ? fraction | (std::uint64_t(1) << 52) : fraction;
    const long e = biased > 0 ? biased - 1075 : -1074;
    // m^2 in two 64-bit words, from m = h 2^32 + l (h below 2^21).
    const std::uint64_t h = m >> 32, l = m & 0xffffffffu;
    const std::uint64_t cross = 2 * h * l;  // below 2^54
    const std::uint64_t low_square = l * l, low = low_square + (cross << 32);
    const std::uint64_t high = h * h + (cross >> 32) + (low < low_square ? 1 : 0);
    const long width = high ? 64 + std::bit_width(high) : std::bit_width(low);
    return width - 1 + 2 * e;
}

double ulps_away(double v, int n) { return std::bit_cast<double>(std::bit_cast<std::uint64_t>(v) + static_cast<std::int64_t>(n)); }

// Both edges of every half octave of the normal range, a few ulps either side: 2^j exactly, and the
// doubles around sqrt(2) 2^j, where a rounded log2 goes wrong.
TEST(HalfOctave, IsExactAtEveryEdge) {
    for (int j = -1021; j <= 1023; ++j)
        for (double edge : {std::ldexp(1.0, j), std::ldexp(std::sqrt(2.0), j)}) {
            if (!std::isfinite(edge)) continue;
            for (int n = -3; n <= 3; ++n) {
                const double v = ulps_away(edge, n);
                if (!(v > 0.0) || !std::isfinite(v)) continue;
                ASSERT_EQ(rgb::half_octave(v), exact_half_octave(v)) << std::hexfloat << v;
            }
        }
}

TEST(HalfOctave, IsExactForSubnormalsAndExtremes) {
    const double smallest_normal = std::numeric_limits<double>::min();
    for (double v : {std::numeric_limits<double>::denorm_min(), ulps_away(smallest_normal, -1), smallest_normal / 3,
                     std::sqrt(2.0) * std::ldexp(1.0, -1040), smallest_normal, std::numeric_limits<double>::max()})
        EXPECT_EQ(rgb::half_octave(v), exact_half_octave(v)) << std::hexfloat << v;
    for (int j = -1074; j < -1022; ++j) {
        const double v = std::ldexp(1.0, j);
        EXPECT_EQ(rgb::half_octave(v), exact_half_octave(v)) << std::hexfloat << v;
        EXPECT_EQ(rgb::half_octave(v), 2 * j);
    }
    EXPECT_EQ(rgb::half_octave(1.0), 0);
    EXPECT_EQ(rgb::half_octave(1.5), 1);  // 1.5^2 = 2.25
    EXPECT_EQ(rgb::half_octave(0.75), -1);
}

TEST(HalfOctave, IsExactForRandomValues) {
    std::mt19937_64 random(20261202);
    for (int i = 0; i < 1'000'000; ++i) {
        const double v = std::bit_cast<double>(random() & 0x7fffffffffffffffull);
        if (!(v > 0.0) || !std::isfinite(v)) continue;
        ASSERT_EQ(rgb::half_octave(v), exact_half_octave(v)) << std::hexfloat << v;
    }
}

}  // namespace
}  // namespace rgbtest
