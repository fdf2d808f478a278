#pragma once
// "Set all to level N": every face refined or coarsened to level N, coarse to fine, as a RequestJob
// of canonical pieces (request_pieces.h); the script line `level N` says it exactly.
#include <memory>

#include "app/request_job.h"

namespace rgb {
class Mesh;
}

namespace app {

std::unique_ptr<RequestJob> make_flood_fill(rgb::Mesh& mesh, int level);

}  // namespace app
