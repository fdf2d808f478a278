#include "rgb/address_index.h"

namespace rgb {

std::size_t AddressIndex::home(const SurfacePoint& p) const {
    std::uint32_t h = p.a[0] * 0x9e3779b1u ^ a1_level(p) * 0x85ebca77u;
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 13;
    // Lemire's range reduction: uniform over a region of any size, without a division.
    const std::size_t size = region_start_[p.face + 1] - region_start_[p.face];
    return region_start_[p.face] + static_cast<std::size_t>((std::uint64_t(h) * size) >> 32);
}

AddressIndex::AddressIndex(std::span<const SurfacePoint> points, std::size_t num_base_faces) {
    // Two slots per vertex of the face: probe sequences stay short.
    region_start_.assign(num_base_faces + 1, 0);
    for (const SurfacePoint& p : points) region_start_[p.face + 1] += 2;
    for (std::size_t f = 0; f < num_base_faces; ++f) region_start_[f + 1] += region_start_[f];
    entries_.resize(region_start_.back());
    // Vertices are inserted face by face (each region is then filled while it is in cache), each face
    // in vertex order, so a repeat is found at the later of the two vertices.
    std::vector<std::uint32_t> cursor(region_start_.begin(), region_start_.end() - 1), order(points.size());
    for (std::uint32_t& c : cursor) c /= 2;
    for (std::uint32_t v = 0; v < points.size(); ++v) order[cursor[points[v].face]++] = v;
    for (std::uint32_t v : order) {
        const SurfacePoint& p = points[v];
        const std::size_t begin = region_start_[p.face], end = region_start_[p.face + 1];
        const std::uint32_t a1l = a1_level(p);
        for (std::size_t s = home(p);; s = s + 1 == end ? begin : s + 1) {
            Entry& e = entries_[s];
            if (e.vertex == kAbsent) {
                e = {p.a[0], a1l, v};
                break;
            }
            if (e.a0 == p.a[0] && e.a1_level == a1l) {
                if (!first_repeat_ || v < *first_repeat_) first_repeat_ = v;
                break;
            }
        }
    }
}

std::uint32_t AddressIndex::find(const SurfacePoint& p) const {
    const std::size_t begin = region_start_[p.face], end = region_start_[p.face + 1];
    if (begin == end) return kAbsent;
    const std::uint32_t a1l = a1_level(p);
    for (std::size_t s = home(p);; s = s + 1 == end ? begin : s + 1) {
        const Entry& e = entries_[s];
        if (e.vertex == kAbsent) return kAbsent;
        if (e.a0 == p.a[0] && e.a1_level == a1l) return e.vertex;
    }
}

}  // namespace rgb
