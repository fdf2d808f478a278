// The LOD driver's room (speed machinery beside the canonical order, canonical_order.h): a run with
// every split wanted reserves the mesh's and its own arrays for the budget at once, so they never
// regrow on the way (a regrowth copied the whole mesh at the last step), and faults their pages in
// on another core ahead of the writes (Prefault: on the build machine a page costs about 5 us at
// first access; reading the pages ahead took the budget engine from 804 to 593 ms at 1.5M
// triangles, docs/benchmarks.md).
#include "rgb/lod/lod_driver.h"

#include <algorithm>
#include <memory>
#include <span>
#include <vector>

namespace rgb {

// Face slots a run with every split wanted may fill, from the base: its budget and the split that
// crosses it, or, where the level cap binds first, the uniform mesh at the cap (room reserved and
// faulted in for a budget the run cannot reach would only take memory).
std::size_t LodDriver::room_for_run() const {
    const std::size_t budget = settings_.max_triangles + settings_.max_triangles / 64 + 64;
    if (settings_.max_level >= 16) return budget;
    return std::min(budget, mesh_.num_faces() << (2 * std::max(settings_.max_level, 0)));
}

// Face slots a threshold run of the default value (max-edge over the whole surface) will fill, from
// the base: a face whose edges are r times the threshold on average split about log2(r) levels deep
// (triangles_down_to; 0.7-1.3 times what the runs made on the benchmark meshes); 0 for other values, whose sizes are not estimated (those runs
// grow their arrays as they go).
std::size_t LodDriver::room_for_threshold() const {
    if (!plain_edge_length_ || !(settings_.threshold > 0.0)) return 0;
    double shortest = 0.0, triangles = 0.0;
    for (double edge : base_mean_edges(shortest)) triangles += triangles_down_to(edge, settings_.threshold);
    return static_cast<std::size_t>(std::min(triangles, static_cast<double>(room_for_run())));
}

// Room for the run in the mesh (face and vertex slots, `limits` entries of its table of limits) and
// in the driver, with the threads that fault it in ahead started where they are not running: again
// after a uniform start undone, whose copy of the mesh has a table of limits without the room and
// whose assignment stopped the threads (a run on from there faulted the rest of its room in on its
// own thread, and its table grew as it went).
void LodDriver::reserve_room(std::size_t faces, std::size_t vertices, std::size_t limits) {
    mesh_.reserve(faces, vertices);
    mesh_.reserve_limits(limits);
    // The start's limits then land all over the table: its pages are faulted in on another core
    // meanwhile (33 ms of the main thread's time at 1.5M on a machine with slow page faults).
    if (!limit_prefault_) limit_prefault_ = std::make_unique<Prefault>(std::vector{mesh_.limit_table()});
    if (face_added_.size() < faces) {
        stop_room_prefault();
        face_added_.resize(faces);
    }
    if (!prefault_) prefault_room(faces, vertices);
}

// The room reserved for the run (face and vertex slots), in the mesh and in the driver's arrays, and
// room for its candidates, faulted in on another core ahead of the splits that fill it. Before the
// uniform start, whose new vertices fill the driver's arrays too (refine_uniform faults in the mesh's
// part as well: the second pass over those pages finds them present).
void LodDriver::prefault_room(std::size_t faces, std::size_t vertices) {
    auto more = [](std::size_t total, std::size_t used) { return total > used ? total - used : 0; };
    std::vector<std::span<std::byte>> room =
        mesh_.room_ahead(more(faces, mesh_.face_capacity()), more(vertices, mesh_.vertex_capacity()));
    const std::size_t used = mesh_.vertex_capacity();
    auto tail = [&room](auto& array, std::size_t from) {
        if (from < array.size()) room.push_back(std::as_writable_bytes(std::span(array).subspan(from)));
    };
    tail(vertex_key_, used);
    tail(base_space_, used);
    tail(limit_known_, used);
    tail(limit_, used);
    tail(face_added_, mesh_.face_capacity());
    // The candidates queued at once: the run queues each green edge its splits make, about 1.7 per
    // triangle it adds (2.4M on the way to 1.5M triangles on a torus), and hands back the chunks of
    // each band it works off; at most 1.0 per triangle of the budget are held at once there (1.51M),
    // so 1.25 leaves room to spare without faulting in pages never used (a third of the pool was).
    // More than that grows the pool, whose new chunks then fault in as they are written.
    // All of the pool, not only what reserve adds: after a uniform start undone (whose faulting-in
    // stopped part way) the pool has the room, untouched for the most part, and reserve adds none.
    bands_.reserve(faces + faces / 4);
    for (std::span<std::byte> block : bands_.memory()) room.push_back(block);
    // The longest band: 457k candidates there (30% of the budget); a longer one grows the list.
    for (ZeroedVector<Candidate>* list : {&band_list_, &band_spare_}) {
        list->reserve(faces * 2 / 5);
        room.push_back(std::as_writable_bytes(std::span(list->data(), list->capacity())));
    }
    prefault_ = std::make_unique<Prefault>(std::move(room));
}

// The threads read the pages they fault in (prefault.h), so they stop before any of the arrays they
// cover moves: a run past the room reserved, which only slows what follows. The room's covers the
// driver's arrays and the mesh's; the table's, only the mesh's table of limits.
void LodDriver::stop_room_prefault() { prefault_.reset(); }

void LodDriver::arrays_moving(const Mesh&) {
    prefault_.reset();
    limit_prefault_.reset();
}

}  // namespace rgb
