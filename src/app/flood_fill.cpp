#include "app/flood_fill.h"

#include <string>

#include "app/request_pieces.h"

namespace app {

std::unique_ptr<RequestJob> make_flood_fill(rgb::Mesh& mesh, int level) {
    auto job = std::make_unique<RequestJob>(mesh, "set all to level " + std::to_string(level), false);
    job->add([&mesh, level] { return set_all_pieces(mesh, level); }, "level " + std::to_string(level) + "\n");
    return job;
}

}  // namespace app
