#include "rgb/mesh/address_index.h"

namespace rgb {

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
        for (std::size_t s = home(p, begin, end);; s = s + 1 == end ? begin : s + 1) {
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

}  // namespace rgb
