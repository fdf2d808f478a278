#include "io/mesh_file.h"

#include <stdexcept>

#include <glm/geometric.hpp>

#include "io/atomic_file.h"
#include "io/number_format.h"
#include "io/obj_error.h"
#include "io/obj_reader.h"
#include "io/state_format.h"
#include "io/truncation_check.h"
#include "rgb/loop_geometry.h"

namespace rgbio {

namespace {

std::vector<glm::dvec3> written_positions(const rgb::Mesh& mesh, SavedPositions which, std::vector<std::uint32_t>& obj_index,
                                          SaveReport& report) {
    std::vector<glm::dvec3> positions;
    positions.reserve(mesh.num_vertices());
    obj_index.assign(mesh.vertex_capacity(), UINT32_MAX);
    for (rgb::VertexId v : mesh.vertices()) {
        obj_index[v.idx] = static_cast<std::uint32_t>(positions.size());
        std::optional<glm::dvec3> limit;
        if (which == SavedPositions::Limit) {
            limit = rgb::try_limit_position(mesh, v);
            if (!limit) ++report.limit_fallbacks;
        }
        positions.push_back(limit ? *limit : rgb::displayed_position(mesh, v));
    }
    return positions;
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

rgb::Mesh build_mesh(const LoadedMesh& loaded, const std::string& file) {
    try {
        if (loaded.state) return rgb::restore_state(*loaded.state);
        return rgb::Mesh(loaded.positions, loaded.triangles);
    } catch (const std::invalid_argument& e) {
        // The loader hands only validated meshes to the core, so this is a corrupt saved state.
        throw ObjError(ObjProblem::BadState, file, 0, std::string("the saved rgbsub state is not a valid RGB mesh: ") + e.what());
    }
}

rgb::Mesh load_mesh(const std::string& path, std::vector<std::string>* warnings, const ReadOptions& options) {
    const LoadedMesh loaded = read_obj_file(path, options);
    if (warnings) warnings->insert(warnings->end(), loaded.warnings.begin(), loaded.warnings.end());
    return build_mesh(loaded, path);
}

std::string format_obj(const rgb::Mesh& mesh, const SaveOptions& options, SaveReport* report) {
    SaveReport local;
    std::vector<std::uint32_t> obj_index;
    const std::vector<glm::dvec3> positions = written_positions(mesh, options.positions, obj_index, local);
    std::vector<rgb::Triangle> triangles;
    triangles.reserve(mesh.num_faces());
    for (rgb::FaceId f : mesh.faces()) {
        const auto& v = mesh.face_vertices(f);
        triangles.push_back({obj_index[v[0].idx], obj_index[v[1].idx], obj_index[v[2].idx]});
    }

    std::string out = "# rgbsub mesh: " + std::to_string(positions.size()) + " vertices, " + std::to_string(triangles.size()) +
                      " triangles; positions: " + (options.positions == SavedPositions::Limit ? "limit" : "displayed") +
                      // Lets the reader tell a file cut before its state from one saved without it.
                      (options.state ? std::string(kSavedStateNote) : std::string()) + "\n";
    out.reserve(out.size() + 40 * positions.size() + 30 * triangles.size());
    for (const glm::dvec3& p : positions) {
        out += 'v';
        for (int i = 0; i < 3; ++i) append_double(out, p[i]);
        out += '\n';
    }
    if (options.normals)
        for (const glm::dvec3& n : vertex_normals(positions, triangles)) {
            out += "vn";
            for (int i = 0; i < 3; ++i) append_double(out, n[i]);
            out += '\n';
        }
    for (const rgb::Triangle& t : triangles) {
        out += 'f';
        for (std::uint32_t v : t) {
            const std::string index = std::to_string(std::size_t(v) + 1);
            out += ' ' + index;
            if (options.normals) out += "//" + index;
        }
        out += '\n';
    }
    if (options.state) out += format_state(rgb::capture_state(mesh));
    if (report) *report = local;
    return out;
}

SaveReport save_mesh(const rgb::Mesh& mesh, const std::string& path, const SaveOptions& options) {
    SaveReport report;
    write_file_atomically(path, format_obj(mesh, options, &report));
    return report;
}

}  // namespace rgbio
