#include "rgb/outgoing_halfedges.h"

#include <algorithm>

namespace rgb {

// Grouped in parallel blocks of start vertices: each block's thread reads all the faces, in order,
// and keeps the corners at its own vertices, so that counting and filling (random writes over 8
// bytes per corner, the slow part) run on all cores and no thread writes where another does.
OutgoingHalfedges outgoing_halfedges(std::span<const Triangle> faces, std::size_t nv) {
    OutgoingHalfedges out;
    out.start.assign(nv + 1, 0);
    const std::size_t blocks = parallel_blocks(nv, 1 << 16);
    auto for_corners_at = [&faces](std::size_t begin, std::size_t end, const auto& f) {
        const auto first = static_cast<std::uint32_t>(begin), count = static_cast<std::uint32_t>(end - begin);
        for (std::uint32_t face = 0; face < faces.size(); ++face)
            for (std::uint32_t c = 0; c < 3; ++c)
                if (faces[face][c] - first < count) f(face, c);
    };
    parallel_blocks_for(nv, blocks, [&](std::size_t, std::size_t begin, std::size_t end) {
        for_corners_at(begin, end, [&](std::uint32_t f, std::uint32_t c) { ++out.start[faces[f][c] + 1]; });
    });
    for (std::size_t v = 0; v < nv; ++v) out.start[v + 1] += out.start[v];
    out.entries.reset(new std::uint64_t[3 * faces.size()]);
    std::vector<std::optional<OutgoingHalfedges::Repeat>> repeating(blocks);
    parallel_blocks_for(nv, blocks, [&](std::size_t b, std::size_t begin, std::size_t end) {
        std::vector<std::uint32_t> cursor(out.start.begin() + static_cast<std::ptrdiff_t>(begin), out.start.begin() + static_cast<std::ptrdiff_t>(end));
        for_corners_at(begin, end, [&](std::uint32_t f, std::uint32_t c) {
            out.entries[cursor[faces[f][c] - begin]++] = std::uint64_t(faces[f][(c + 1) % 3]) << 32 | (3 * f + c);
        });
        for (std::size_t v = begin; v < end; ++v) {
            std::sort(out.entries.get() + out.start[v], out.entries.get() + out.start[v + 1]);
            const auto group = out.of(static_cast<std::uint32_t>(v));
            for (std::size_t k = 1; k < group.size() && !repeating[b]; ++k)
                if (OutgoingHalfedges::end_vertex(group[k]) == OutgoingHalfedges::end_vertex(group[k - 1]))
                    repeating[b] = {static_cast<std::uint32_t>(v), OutgoingHalfedges::end_vertex(group[k]), OutgoingHalfedges::halfedge(group[k]) / 3};
            if (repeating[b]) break;
        }
    });
    for (const auto& repeat : repeating)
        if (repeat && !out.repeating) out.repeating = repeat;
    return out;
}

}  // namespace rgb
