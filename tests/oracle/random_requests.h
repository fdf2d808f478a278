#pragma once
// Random region requests for the Far agreement tests: balls around base vertices, of radii from a
// tenth of an edge to two edges, of one kind (0 refine, 1 set, 2 coarsen) or, with -1, of every kind.
#include <random>
#include <vector>

#include "osd_far.h"
#include "rgb/lod/requests.h"

namespace osdoracle {

std::vector<rgb::LevelRequest> random_requests(const FarInput& in, std::mt19937& rng, int count, int fixed_kind);

}  // namespace osdoracle
