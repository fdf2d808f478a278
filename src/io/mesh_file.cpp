#include "io/mesh_file.h"

#include <stdexcept>
#include <string_view>

#include <glm/geometric.hpp>

#include "io/atomic_file.h"
#include "io/crease_tags.h"
#include "io/number_format.h"
#include "io/obj_error.h"
#include "io/obj_reader.h"
#include "io/state_format.h"
#include "io/truncation_check.h"
#include "rgb/loop_geometry.h"

namespace rgbio {

namespace {

glm::dvec3 written_position(const rgb::Mesh& mesh, rgb::VertexId v, SavedPositions which) {
    return which == SavedPositions::Limit ? rgb::limit_position(mesh, v) : rgb::displayed_position(mesh, v);
}

std::vector<glm::dvec3> vertex_normals(const std::vector<glm::dvec3>& positions, const std::vector<rgb::Triangle>& triangles) {
    std::vector<glm::dvec3> normals(positions.size(), glm::dvec3(0.0));
    for (const rgb::Triangle& t : triangles) {
        // The cross product's length is twice the area, so the sum is area-weighted.
        const glm::dvec3 n = glm::cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]);
        for (std::uint32_t v : t) normals[v] += n;
    }
    for (glm::dvec3& n : normals)
        if (glm::length(n) > 0) n = glm::normalize(n);
    return normals;
}

}  // namespace

rgb::Mesh build_mesh(const LoadedMesh& loaded) {
    if (loaded.adaptive) return *loaded.adaptive;
    return rgb::Mesh(std::make_shared<const rgb::BaseMesh>(loaded.positions, loaded.triangles, loaded.sharp_features));
}

rgb::Mesh load_mesh(const std::string& path, std::vector<std::string>* warnings, const ReadOptions& options) {
    LoadedMesh loaded = read_obj_file(path, options);
    if (warnings) warnings->insert(warnings->end(), loaded.warnings.begin(), loaded.warnings.end());
    if (loaded.adaptive) return std::move(*loaded.adaptive);
    return build_mesh(loaded);
}

namespace {

// The text collected in one string (format_obj).
struct StringOutput {
    std::string text;
    std::string& buffer() { return text; }
    void flush_if_full() {}
};

// Appends the OBJ text record by record; Output is StringOutput or AtomicFileWriter (save_mesh
// streams the file instead of holding it whole). Positions and triangles are computed as they are
// written; only normals, which need them all first, keep them in arrays.
template <class Output>
void write_obj(const rgb::Mesh& mesh, const SaveOptions& options, Output& output) {
    std::string& out = output.buffer();
    out += "# rgbsub mesh: " + std::to_string(mesh.num_vertices()) + " vertices, " + std::to_string(mesh.num_faces()) +
           " triangles; positions: " + (options.positions == SavedPositions::Limit ? "limit" : "displayed") +
           // Lets the reader tell a file cut before its state from one saved without it.
           (options.state ? std::string(kSavedStateNote) : std::string()) + "\n";
    std::vector<std::uint32_t> obj_index(mesh.vertex_capacity(), UINT32_MAX);
    std::vector<glm::dvec3> positions;
    if (options.normals) positions.reserve(mesh.num_vertices());
    std::uint32_t written = 0;
    for (rgb::VertexId v : mesh.vertices()) {
        obj_index[v.idx] = written++;
        const glm::dvec3 p = written_position(mesh, v, options.positions);
        if (options.normals) positions.push_back(p);
        out += 'v';
        for (int i = 0; i < 3; ++i) append_double(out, p[i]);
        out += '\n';
        output.flush_if_full();
    }
    auto triangle = [&](rgb::FaceId f) {
        const auto& v = mesh.face_vertices(f);
        return rgb::Triangle{obj_index[v[0].idx], obj_index[v[1].idx], obj_index[v[2].idx]};
    };
    if (options.normals) {
        std::vector<rgb::Triangle> triangles;
        triangles.reserve(mesh.num_faces());
        for (rgb::FaceId f : mesh.faces()) triangles.push_back(triangle(f));
        for (const glm::dvec3& n : vertex_normals(positions, triangles)) {
            out += "vn";
            for (int i = 0; i < 3; ++i) append_double(out, n[i]);
            out += '\n';
            output.flush_if_full();
        }
    }
    for (rgb::FaceId f : mesh.faces()) {
        out += 'f';
        for (std::uint32_t v : triangle(f)) {
            const std::string index = std::to_string(std::size_t(v) + 1);
            out += ' ' + index;
            if (options.normals) out += "//" + index;
        }
        out += '\n';
        output.flush_if_full();
    }
    append_tag_lines(mesh, obj_index, out);
    if (options.state) write_state(mesh, options.positions == SavedPositions::Limit, out, [&] { output.flush_if_full(); });
}

}  // namespace

std::string format_obj(const rgb::Mesh& mesh, const SaveOptions& options) {
    StringOutput output;
    output.text.reserve(40 * mesh.num_vertices() + 30 * mesh.num_faces());
    write_obj(mesh, options, output);
    return std::move(output.text);
}

void save_mesh(const rgb::Mesh& mesh, const std::string& path, const SaveOptions& options) {
    AtomicFileWriter file(path);
    write_obj(mesh, options, file);
    file.commit();
}

}  // namespace rgbio
