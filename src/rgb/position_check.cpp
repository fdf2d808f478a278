#include "rgb/position_check.h"

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "rgb/loop_geometry.h"
#include "rgb/mesh.h"
#include "rgb/parallel.h"

namespace rgb {

std::size_t count_differing_positions(const Mesh& mesh, std::span<const glm::dvec3> expected, bool limit_positions) {
    if (expected.size() != mesh.num_vertices()) throw std::invalid_argument("count_differing_positions: one position per vertex");
    // The i-th live vertex (a restored mesh has no dead slots: then it is vertex i).
    std::vector<VertexId> gaps;
    if (mesh.num_vertices() != mesh.vertex_capacity())
        for (VertexId v : mesh.vertices()) gaps.push_back(v);
    auto live = [&](std::size_t i) { return gaps.empty() ? VertexId(static_cast<std::uint32_t>(i)) : gaps[i]; };
    const std::size_t n = expected.size();
    // The level each vertex is compared at: its display level, or none (-1) for its limit.
    std::vector<std::int8_t> level(n, -1);
    if (!limit_positions)
        parallel_for(n, 1 << 15, [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) level[i] = static_cast<std::int8_t>(display_level(mesh, live(i)));
        });
    for (std::size_t i = 0; i < n; ++i)
        if ((level[i] < 0 || level[i] > mesh.level(live(i))) && !mesh.has_cached_limit(live(i))) limit_position(mesh, live(i));
    const std::size_t blocks = parallel_blocks(n, 1 << 15);
    std::vector<std::size_t> differing(blocks, 0);
    parallel_blocks_for(n, blocks, [&](std::size_t b, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const glm::dvec3 p = level[i] < 0 ? limit_position(mesh, live(i)) : control_point(mesh, live(i), level[i]);
            differing[b] += p != expected[i];
        }
    });
    std::size_t total = 0;
    for (std::size_t d : differing) total += d;
    return total;
}

}  // namespace rgb
