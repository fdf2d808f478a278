#pragma once
// A few grids of base faces (face_grid_limits.h) kept at once, for a caller whose points come from
// several faces in turn rather than one face after another: the tolerance criterion (limit_error.h),
// which the LOD driver asks for edges band by band in Morton order, so that consecutive edges mostly
// lie in the same few base faces, each met again and again. Each face asked for gets a grid, the
// one used longest ago giving way; a grid started for a coarser level than asked starts again deeper.
// Every value is the evaluator's, bit for bit, whichever grid gives it.
//
// Not for several threads at once: a caller that works on several keeps a cache per thread (the grids
// fill on demand, and their evaluator's tables with them).
#include <cstdint>
#include <memory>
#include <vector>

#include "rgb/values/face_grid_limits.h"

namespace rgb {

class BaseMesh;
class HierarchyEvaluator;

class FaceGridCache {
public:
    // `evaluator` is over `base`; it answers for the points on the faces' boundaries and those deeper
    // than kDeepestGrid.
    FaceGridCache(const BaseMesh& base, HierarchyEvaluator& evaluator, std::size_t grids = kGrids);

    // A grid started on base face `face` for points up to `level` (at most kDeepestGrid; deeper points
    // are the evaluator's through it).
    FaceGridLimits& grid(std::uint32_t face, int level);

    // A few more than the faces an edge's two triangles and its neighbours in a band's Morton run meet
    // (not tuned: docs/benchmarks.md "Detail criteria").
    static constexpr std::size_t kGrids = 8;
    // (2^8 + 1)^2 slots, 3.7 MB a grid, 30 MB for kGrids (at FaceGridLimits::kMaxLevel, 15 MB a grid):
    // the samples of triangles of level 6 and coarser, where nearly all of a tolerance's work is.
    static constexpr int kDeepestGrid = 8;

private:
    struct Entry {
        std::unique_ptr<FaceGridLimits> grid;
        std::uint64_t used = 0;  // when it was last asked for
        bool started = false;
    };
    std::vector<Entry> entries_;
    std::uint64_t clock_ = 0;
};

}  // namespace rgb
