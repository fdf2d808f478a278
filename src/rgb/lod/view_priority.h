#pragma once
// The order in which the view-dependent updater (view_lod.h) visits faces, so that the picture gets
// useful soonest while the camera moves: faces that may be seen before the others, then coarse
// before fine (by the level of the green edges a visit may split), then those largest on screen (the
// nearest) first. A face's bucket is one number in that order, from its edges' levels and its
// corners' base-space positions: cheap enough to compute for every face of a pass, and only an
// estimate (every face is still judged edge by edge).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "rgb/lod/screen_detail.h"
#include "rgb/mesh/handles.h"
#include "rgb/mesh/mesh.h"

namespace rgb {

// Half-octave bands of on-screen size, from 2^20 pixels down to 1 (smaller ones share the last).
inline constexpr int kViewSizeBands = 40;
inline constexpr std::size_t kViewBuckets = 2 * (kMaxLevel + 1) * kViewSizeBands;

// The bucket of face f for the criterion's camera, for splitting its coarsest green edges of level
// `from_level` or finer: lower buckets are visited first. None when f has no such edge.
std::optional<std::size_t> view_bucket(const Mesh& mesh, const ScreenCriterion& criterion, FaceId f, int from_level = 0);

// Faces by bucket, taken lowest bucket first (in a bucket, last in first out).
class FaceBuckets {
public:
    struct Taken {
        FaceId face;
        int level = 0;  // of the green edges the face's bucket is for
    };
    FaceBuckets() : buckets_(kViewBuckets) {}
    void push(std::size_t bucket, FaceId f);
    std::optional<Taken> pop();
    // Whether every face left is one that may not be seen.
    bool only_unseen_left() const { return lowest_ >= kViewBuckets / 2; }
    void clear();

private:
    std::vector<std::vector<FaceId>> buckets_;
    std::size_t lowest_ = kViewBuckets;  // no face in a bucket below
};

}  // namespace rgb
