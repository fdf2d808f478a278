#pragma once
// Work that may take seconds cut into canonical pieces, applied one after another coarse to fine, so
// that the display can follow and the work can stop between pieces (docs/requests.md, "What a request means"):
//   - a refine request to level N is its requests to levels 1..N (the bands of its taper capped at
//     each level): each asks a subset of what it asks, and together they ask all of it;
//   - a request restricted to a batch of the base faces it meets asks a part of what it asks, and
//     the batches together ask all of it;
//   - a set request is its coarsen part, then its refine part.
// Pieces of one kind commute, so the pieces in order give the identical mesh to the request whole.
#include <cstdint>
#include <vector>

#include "rgb/lod/dab.h"
#include "rgb/lod/requests.h"

namespace rgb {
class Mesh;
}

namespace app {

// About this many visited and new triangles per piece: several milliseconds of engine time.
inline constexpr double kPieceTriangles = 8192.0;

// The pieces of a dab (none when apply_dab would do nothing); the whole request as one piece when it
// is expected to be small. Levels up to `from_level` (the level of the face under the dab, say) get
// no pieces of their own; that changes the slicing only, never the result.
std::vector<rgb::LevelRequest> dab_pieces(const rgb::Mesh& mesh, const rgb::Dab& dab, int from_level,
                                          double piece_triangles = kPieceTriangles);

// The base faces a request may touch: those its outermost ball meets (every base face without a
// ball), within its own restriction if it has one; sorted. The request restricted to any partition
// of them, piece by piece, gives the mesh of the request whole.
std::vector<std::uint32_t> request_base_faces(const rgb::Mesh& mesh, const rgb::LevelRequest& request);

// The pieces of "every face to level N", the levels below the mesh's coarsest face skipped.
std::vector<rgb::LevelRequest> set_all_pieces(const rgb::Mesh& mesh, int level, double piece_triangles = kPieceTriangles);

}  // namespace app
