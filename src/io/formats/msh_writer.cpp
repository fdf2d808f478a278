#include "io/formats/format_writers.h"

#include <algorithm>

#include <glm/common.hpp>

#include "io/files/atomic_file.h"
#include "io/obj/number_format.h"

namespace rgbio {

namespace {

// One $ElementData view: a scalar per element, elements numbered from 1.
template <class Value>
void write_element_data(AtomicFileWriter& file, const char* name, std::size_t count, Value value) {
    std::string& out = file.buffer();
    out += std::string("$ElementData\n1\n\"") + name + "\"\n1\n0\n3\n0\n1\n" + std::to_string(count) + "\n";
    for (std::size_t t = 0; t < count; ++t) {
        append_digits(out, t + 1);
        value(out, t);
        out += '\n';
        file.flush_if_full();
    }
    out += "$EndElementData\n";
}

}  // namespace

void save_msh(const ExportMesh& mesh, const std::string& path) {
    AtomicFileWriter file(path);
    std::string& out = file.buffer();
    const std::size_t n = mesh.positions.size(), m = mesh.triangles.size();
    // One surface entity (tag 1) holding every node and triangle, with the mesh's bounding box.
    glm::dvec3 lo(0.0), hi(0.0);
    if (n > 0) lo = hi = mesh.positions[0];
    for (const glm::dvec3& p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    out += "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 1 0\n1";
    for (const glm::dvec3& corner : {lo, hi})
        for (int i = 0; i < 3; ++i) append_double(out, corner[i]);
    out += " 0 0\n$EndEntities\n$Nodes\n1 " + std::to_string(n) + " 1 " + std::to_string(n) + "\n2 1 0 " + std::to_string(n) + "\n";
    for (std::size_t v = 0; v < n; ++v) {
        append_digits(out, v + 1);
        out += '\n';
        file.flush_if_full();
    }
    for (const glm::dvec3& p : mesh.positions) {
        for (int i = 0; i < 3; ++i) append_double(out, p[i]);
        out += '\n';
        file.flush_if_full();
    }
    out += "$EndNodes\n$Elements\n1 " + std::to_string(m) + " 1 " + std::to_string(m) + "\n2 1 2 " + std::to_string(m) + "\n";
    for (std::size_t t = 0; t < m; ++t) {
        append_digits(out, t + 1);
        for (std::uint32_t v : mesh.triangles[t]) append_integer(out, std::uint64_t{v} + 1);
        out += '\n';
        file.flush_if_full();
    }
    out += "$EndElements\n";
    write_element_data(file, "level", m, [&](std::string& o, std::size_t t) { append_integer(o, mesh.levels[t]); });
    write_element_data(file, "rgb_colour", m, [&](std::string& o, std::size_t t) { append_integer(o, mesh.rgb_colours[t]); });
    const std::vector<rgb::TriangleQuality> quality = triangle_qualities(mesh);
    write_element_data(file, "quality", m, [&](std::string& o, std::size_t t) { append_double(o, quality[t].aspect_ratio); });
    write_element_data(file, "min_angle", m, [&](std::string& o, std::size_t t) { append_double(o, quality[t].min_angle); });
    file.commit();
}

}  // namespace rgbio
