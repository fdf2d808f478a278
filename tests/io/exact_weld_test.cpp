// Welding by exact position in parallel (io/formats/exact_weld.h) against a plain ordered map: per
// point, the first used point equal to it (+0 and -0 alike, NaN equal to nothing), for arrays small
// enough for one bucket and large enough for several.
#include <cmath>
#include <map>
#include <random>

#include <gtest/gtest.h>

#include "io/formats/exact_weld.h"

namespace rgbio {
namespace {

std::vector<std::uint32_t> first_equal_by_map(const std::vector<glm::dvec3>& points, const std::vector<std::uint8_t>& used) {
    std::map<std::array<double, 3>, std::uint32_t> first_at;
    std::vector<std::uint32_t> out(points.size(), UINT32_MAX);
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        if (!used[i]) continue;
        const glm::dvec3& p = points[i];
        if (std::isnan(p.x) || std::isnan(p.y) || std::isnan(p.z)) {
            out[i] = i;
            continue;
        }
        out[i] = first_at.try_emplace({p.x + 0.0, p.y + 0.0, p.z + 0.0}, i).first->second;
    }
    return out;
}

TEST(ExactWeld, FirstEqualPointsAsAMapFindsThem) {
    for (const std::size_t n : {std::size_t(7), std::size_t(20000)}) {  // one bucket; sixteen
        std::mt19937 random(7);
        std::uniform_int_distribution<int> pick(0, 9);
        std::vector<glm::dvec3> points;
        std::vector<std::uint8_t> used;
        for (std::size_t i = 0; i < n; ++i) {
            // A point of a small grid repeats often; signs of zero vary; some points are unused or NaN.
            const int a = pick(random), b = pick(random), c = static_cast<int>(i % 50);
            const double zero = pick(random) < 5 ? 0.0 : -0.0;
            points.emplace_back(a == 0 ? zero : a * 0.1, b, c == 3 && a == 1 ? std::nan("") : c * 0.01);
            used.push_back(pick(random) != 0);
        }
        EXPECT_EQ(first_equal_points(points, used), first_equal_by_map(points, used)) << n;
    }
}

}  // namespace
}  // namespace rgbio
