#include "io/formats/format_writers.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "io/files/atomic_file.h"

namespace rgbio {

void save_stl(const ExportMesh& mesh, const std::string& path) {
    AtomicFileWriter file(path);
    std::string& out = file.buffer();
    std::string header = "binary STL written by rgbsub";
    header.resize(80, ' ');
    out += header;
    append_bytes(out, static_cast<std::uint32_t>(mesh.triangles.size()));
    for (const rgb::Triangle& t : mesh.triangles) {
        // The normal of the triangle a reader sees: the one of its float corners.
        const glm::vec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
        const glm::vec3 n = glm::cross(b - a, c - a);
        const float length = glm::length(n);
        const glm::vec3 normal = length > 0.0f ? n / length : glm::vec3(0.0f);
        for (const glm::vec3& p : {normal, a, b, c})
            for (int i = 0; i < 3; ++i) append_bytes(out, p[i]);
        append_bytes(out, std::uint16_t{0});  // attribute byte count
        file.flush_if_full();
    }
    file.commit();
}

}  // namespace rgbio
