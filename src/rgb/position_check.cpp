#include "rgb/position_check.h"

#include <stdexcept>
#include <vector>

#include "rgb/loop_geometry.h"
#include "rgb/mesh.h"
#include "rgb/parallel.h"

namespace rgb {

std::size_t count_differing_positions(const Mesh& mesh, std::span<const glm::dvec3> expected, bool limit_positions) {
    if (expected.size() != mesh.num_vertices()) throw std::invalid_argument("count_differing_positions: one position per vertex");
    std::vector<VertexId> live;
    live.reserve(mesh.num_vertices());
    for (VertexId v : mesh.vertices()) live.push_back(v);
    // The level each vertex is compared at: its display level, or none (-1) for its limit.
    std::vector<int> level(live.size(), -1);
    if (!limit_positions)
        parallel_for(live.size(), 1 << 15, [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) level[i] = display_level(mesh, live[i]);
        });
    for (std::size_t i = 0; i < live.size(); ++i)
        if ((level[i] < 0 || level[i] > mesh.level(live[i])) && !mesh.cached_limit(live[i])) limit_position(mesh, live[i]);
    const std::size_t blocks = parallel_blocks(live.size(), 1 << 15);
    std::vector<std::size_t> differing(blocks, 0);
    parallel_blocks_for(live.size(), blocks, [&](std::size_t b, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const glm::dvec3 p = level[i] < 0 ? limit_position(mesh, live[i]) : control_point(mesh, live[i], level[i]);
            differing[b] += p != expected[i];
        }
    });
    std::size_t total = 0;
    for (std::size_t d : differing) total += d;
    return total;
}

}  // namespace rgb
