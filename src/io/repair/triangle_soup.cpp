#include "io/repair/triangle_soup.h"

#include <algorithm>
#include <functional>

#include "rgb/support/bucket_sort.h"

namespace rgbio {

void TriangleSoup::flip(std::size_t t) {
    std::swap(triangles[t][1], triangles[t][2]);
    if (!texcoords.empty()) std::swap(texcoords[t][1], texcoords[t][2]);
}

std::uint32_t TriangleSoup::copy_vertex(std::uint32_t v) {
    vertex_origin.push_back(vertex_origin[v]);
    return static_cast<std::uint32_t>(vertex_origin.size() - 1);
}

std::vector<EdgeUse> edge_uses(const std::vector<rgb::Triangle>& triangles) {
    std::size_t vertices = 0;
    for (const rgb::Triangle& t : triangles)
        for (std::uint32_t v : t) vertices = std::max<std::size_t>(vertices, std::size_t(v) + 1);
    auto uses = [&](auto&& emit) {
        for (std::uint32_t t = 0; t < triangles.size(); ++t)
            for (int i = 0; i < 3; ++i) {
                const std::uint32_t p = triangles[t][i], q = triangles[t][(i + 1) % 3];
                emit(std::min(p, q), EdgeUse{std::min(p, q), std::max(p, q), t});
            }
    };
    return rgb::sorted_by_bucket<EdgeUse>(vertices, uses, std::less<EdgeUse>());
}

}  // namespace rgbio
