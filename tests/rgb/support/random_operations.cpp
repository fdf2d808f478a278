#include "support/random_operations.h"

#include <vector>

#include "rgb/mesh/operators.h"

namespace rgbtest {

rgb::FaceId random_live_face(const rgb::Mesh& mesh, std::mt19937& rng) {
    for (;;) {
        const rgb::FaceId f(static_cast<std::uint32_t>(rng() % mesh.face_capacity()));
        if (mesh.is_live(f)) return f;
    }
}

rgb::VertexId random_live_vertex(const rgb::Mesh& mesh, std::mt19937& rng) {
    for (;;) {
        const rgb::VertexId v(static_cast<std::uint32_t>(rng() % mesh.vertex_capacity()));
        if (mesh.is_live(v)) return v;
    }
}

std::size_t remove_everything_removable(rgb::Mesh& mesh) {
    std::size_t removals = 0;
    for (bool changed = true; changed;) {
        changed = false;
        std::vector<rgb::VertexId> candidates;
        for (rgb::VertexId v : mesh.vertices()) candidates.push_back(v);
        for (rgb::VertexId v : candidates)
            if (mesh.is_live(v) && rgb::can_remove_vertex(mesh, v)) {
                rgb::remove_vertex(mesh, v);
                ++removals;
                changed = true;
            }
    }
    return removals;
}

}  // namespace rgbtest
