#include "stroke_support.h"

#include <glm/geometric.hpp>

#include "rgb/values/loop_geometry.h"

namespace app::test {

std::size_t faces_near(const rgb::Mesh& mesh, std::span<const glm::dvec3> points, double radius) {
    std::size_t count = 0;
    for (rgb::FaceId f : mesh.faces()) {
        bool near = false;
        for (rgb::VertexId v : mesh.face_vertices(f))
            for (const glm::dvec3& p : points) near = near || glm::distance(rgb::displayed_position(mesh, v), p) <= radius;
        count += near;
    }
    return count;
}

}  // namespace app::test
