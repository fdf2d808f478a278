#include "support/clear_threshold.h"

#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

namespace rgbtest {

double clear_threshold(const UniformLoopOracle& oracle, int cap, double share) {
    std::vector<double> lengths;
    for (int j = 0; j < cap; ++j)
        for (const IdentityTriangle& t : oracle.faces(j))
            for (int i = 0; i < 3; ++i) lengths.push_back(oracle_edge_length(oracle, t[i], t[(i + 1) % 3]));
    std::sort(lengths.begin(), lengths.end());
    std::size_t best = 0;
    double best_gap = -1.0;
    const auto target = static_cast<std::size_t>(share * static_cast<double>(lengths.size()));
    for (std::size_t k = target; k + 1 < lengths.size() && k < target + 200; ++k)
        if (lengths[k + 1] - lengths[k] > best_gap) {
            best_gap = lengths[k + 1] - lengths[k];
            best = k;
        }
    const double threshold = 0.5 * (lengths[best] + lengths[best + 1]);
    EXPECT_GT(best_gap, 1e-9 * threshold);
    return threshold;
}

}  // namespace rgbtest
