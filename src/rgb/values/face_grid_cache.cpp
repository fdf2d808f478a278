#include "rgb/values/face_grid_cache.h"

#include <algorithm>

namespace rgb {

FaceGridCache::FaceGridCache(const BaseMesh& base, HierarchyEvaluator& evaluator, std::size_t grids) : entries_(std::max<std::size_t>(grids, 1)) {
    for (Entry& e : entries_) e.grid = std::make_unique<FaceGridLimits>(base, evaluator);
}

FaceGridLimits& FaceGridCache::grid(std::uint32_t face, int level) {
    level = std::min(level, kDeepestGrid);
    ++clock_;
    Entry* oldest = &entries_.front();
    for (Entry& e : entries_) {
        if (e.started && e.grid->face() == face) {
            // Deeper points than it covers would all go to the evaluator: start it again, deeper.
            if (e.grid->level() < level) e.grid->start(face, level);
            e.used = clock_;
            return *e.grid;
        }
        if (e.used < oldest->used) oldest = &e;
    }
    oldest->grid->start(face, level);
    oldest->started = true;
    oldest->used = clock_;
    return *oldest->grid;
}

}  // namespace rgb
