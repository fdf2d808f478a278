#include "rgb/mesh/outgoing_halfedges.h"

#include <atomic>
#include <functional>
#include <optional>

#include "rgb/support/bucket_sort.h"

namespace rgb {

namespace {

// Where a start vertex's group (sorted by end vertex) first holds an end vertex twice, if it does.
std::optional<std::size_t> repeated_end(std::span<const std::uint64_t> group) {
    for (std::size_t k = 1; k < group.size(); ++k)
        if (OutgoingHalfedges::end_vertex(group[k]) == OutgoingHalfedges::end_vertex(group[k - 1])) return k;
    return std::nullopt;
}

}  // namespace

OutgoingHalfedges outgoing_halfedges(std::span<const Triangle> faces, std::size_t nv) {
    auto each_halfedge = [&faces](const auto& emit) {
        for (std::uint32_t f = 0; f < faces.size(); ++f)
            for (std::uint32_t c = 0; c < 3; ++c) emit(faces[f][c], std::uint64_t(faces[f][(c + 1) % 3]) << 32 | (3 * f + c));
    };
    OutgoingHalfedges out;
    out.start = bucket_runs(nv, each_halfedge);
    // Each written once: nothing zero-fills them first.
    out.entries.reset(new std::uint64_t[out.start.back()]);
    // The lowest start vertex with an end vertex twice, whichever thread finds which.
    std::atomic<std::size_t> first_repeating(nv);
    place_in_buckets(std::span<const std::size_t>(out.start), each_halfedge, std::less<std::uint64_t>(), out.entries.get(),
                     [&](std::size_t v, std::span<const std::uint64_t> group) {
                         if (!repeated_end(group)) return;
                         std::size_t lowest = first_repeating.load();
                         while (v < lowest && !first_repeating.compare_exchange_weak(lowest, v)) {
                         }
                     });
    if (const std::size_t v = first_repeating.load(); v < nv) {
        const auto group = out.of(static_cast<std::uint32_t>(v));
        const std::size_t k = *repeated_end(group);
        out.repeating = {static_cast<std::uint32_t>(v), OutgoingHalfedges::end_vertex(group[k]), OutgoingHalfedges::halfedge(group[k]) / 3};
    }
    return out;
}

}  // namespace rgb
