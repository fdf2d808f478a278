#include "io/lod_set_files.h"

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <mutex>
#include <optional>
#include <system_error>
#include <variant>
#include <utility>

#include "io/formats/format_writers.h"
#include "io/formats/mesh_format.h"
#include "io/gltf/gltf_writer.h"
#include "io/gltf_export.h"
#include "io/mesh_export.h"
#include "io/script/triangle_limit.h"
#include "rgb/support/parallel.h"
#include "rgb/values/surface_error.h"

namespace rgbio {

namespace {

// A level's written positions by vertex slot, for the error of the written surface.
std::vector<glm::dvec3> positions_by_slot(const rgb::Mesh& mesh, const std::vector<glm::dvec3>& positions) {
    std::vector<glm::dvec3> out(mesh.vertex_capacity());
    std::size_t k = 0;
    for (rgb::VertexId v : mesh.vertices()) out[v.idx] = positions[k++];
    return out;
}

// Caches the limits of the mesh's live vertices, given in slot order.
void cache_limits(const rgb::Mesh& mesh, const std::vector<glm::dvec3>& limits) {
    mesh.reserve_limits(mesh.num_vertices());
    std::size_t k = 0;
    for (rgb::VertexId v : mesh.vertices()) mesh.cache_limit(v, limits[k++]);
}

// Makes and writes the levels; `written` collects the files as they are written.
LodSet make_levels(const rgb::Mesh& input, const std::vector<ScriptLine>& requests, const LodSetOptions& options,
                   std::vector<std::string>& written) {
    const auto step = [&options, &requests](std::size_t i) {
        if (options.progress && !options.progress(i, requests.size())) throw LodSetStopped();
    };
    const bool writing = options.output.has_value();
    const OutputFormat format = writing ? output_format(*options.output) : OutputFormat::Obj;
    const bool gltf_set = writing && format == OutputFormat::Gltf;
    LodSet set;
    set.size = rgb::bounding_box_diagonal(input.base());
    // Each level is a function of its request alone, so LOD0 is made on this thread while the
    // coarser levels, about a third of its work together, are made, written and measured on another,
    // in order. The switch coverages need only the coarser levels' errors, so LOD0's own file (or the
    // glTF set's one) is then written while LOD0's error is measured: each about as long as the other.
    // (Measured apart, the coarser levels no longer look up LOD0's samples: a sixth more work, on a
    // core that would otherwise wait for LOD0.)
    const std::size_t n = requests.size();
    std::vector<std::optional<LodSetLevel>> made(n);
    std::vector<GltfMesh> gltf(gltf_set ? n : 0);  // for a glTF set: the levels, written together at the end
    // LOD0 with displayed positions is written on its thread while the other writes the coarser
    // levels, so the list of files written is shared.
    std::mutex written_mutex;
    const auto write = [&](const rgb::Mesh& mesh, std::size_t i, const ExportMesh& flat) {
        const std::string file = lod_file_name(*options.output, i);
        if (format == OutputFormat::Obj) save_mesh(mesh, file, options.save);
        else save_export_mesh(flat, file, format, options.save.msh);
        const std::lock_guard lock(written_mutex);
        written.push_back(file);
    };
    std::optional<ExportMesh> lod0_file;  // LOD0 as written, kept until it is
    const auto make = [&](std::size_t i) {
        LodSetLevel& level = made[i].emplace(requests[i], lod_set_level(input, requests[i], options.max_triangles));
        if (gltf_set) {
            gltf[i] = gltf_mesh(level.mesh, options.save);
            level.positions = gltf[i].positions;
            return;
        }
        ExportMesh flat = export_mesh(level.mesh, options.save);
        level.positions = flat.positions;
        if (!writing) return;
        if (i > 0) return write(level.mesh, i, flat);
        // The OBJ writer asks the mesh for limits, which it caches, while the measure reads the mesh:
        // with every limit cached first (the positions just computed) the writer only reads it, and
        // computes none again. With displayed positions it would compute some: written now.
        if (format == OutputFormat::Obj) {
            if (options.save.positions != SavedPositions::Limit) return write(level.mesh, 0, flat);
            cache_limits(level.mesh, level.positions);
        }
        lod0_file = std::move(flat);
    };
    // The errors of levels [first, last), measured together (surface_errors_at).
    std::vector<rgb::SurfaceError> errors(n);
    const auto measure = [&](std::size_t first, std::size_t last) {
        std::vector<const rgb::Mesh*> meshes;
        std::vector<std::vector<glm::dvec3>> corners;
        for (std::size_t i = first; i < last; ++i) {
            meshes.push_back(&made[i]->mesh);
            corners.push_back(positions_by_slot(made[i]->mesh, made[i]->positions));
        }
        const std::vector<rgb::SurfaceError> found = rgb::surface_errors_at(meshes, corners);
        std::copy(found.begin(), found.end(), errors.begin() + static_cast<std::ptrdiff_t>(first));
    };
    // Told of the coarser levels once they are all made: a stop asked for then takes effect there.
    step(0);
    std::atomic<bool> lod0_failed = false;  // then the coarser levels are not wanted
    rgb::parallel_invoke(
        [&] {
            try {
                make(0);
            } catch (...) {
                lod0_failed = true;
                throw;
            }
        },
        [&] {
            for (std::size_t i = 1; i < n && !lod0_failed; ++i) make(i);
            if (!lod0_failed) measure(1, n);
        });
    for (std::size_t i = 1; i < n; ++i) {
        step(i);
        made[i]->nested = positions_nested(made[i]->positions, made[i - 1]->positions);
    }
    for (std::size_t i = 0; gltf_set && i < n; ++i)
        if (const std::optional<std::string> repair = gltf_normal_repair(gltf[i]))
            set.warnings.push_back("LOD" + std::to_string(i) + ": " + *repair);
    step(requests.size());
    std::vector<double> error_values;  // LOD0's is not known yet, and no coverage depends on it
    for (const rgb::SurfaceError& error : errors) error_values.push_back(error.max_error);
    const std::vector<double> coverage = switch_coverage(error_values, set.size);
    rgb::parallel_invoke([&] { measure(0, 1); },
                         [&] {
                             if (lod0_file) write(made[0]->mesh, 0, *lod0_file);
                             if (gltf_set) save_gltf_lods(gltf, coverage, *options.output);
                         });
    lod0_file.reset();
    for (std::size_t i = 0; i < n; ++i) {
        set.levels.push_back(std::move(*made[i]));
        set.levels[i].error = errors[i].max_error;
        set.levels[i].coverage = coverage[i];
    }
    return set;
}

}  // namespace

SavedPositions lod_set_positions(const rgb::Mesh& input) {
    return input.base().detail() ? SavedPositions::Displayed : SavedPositions::Limit;
}

void check_lod_set_size(const rgb::Mesh& input, const std::vector<ScriptLine>& requests, std::size_t max_triangles) {
    for (const ScriptLine& request : requests) {
        if (const auto* level = std::get_if<rgb::LevelRequest>(&request.edit)) check_request_size(input, *level, max_triangles);
        if (const auto* budget = std::get_if<BudgetEdit>(&request.edit)) check_budget_size(budget->triangles, max_triangles);
    }
}

LodSet make_lod_set(const rgb::Mesh& input, const std::vector<ScriptLine>& requests, const LodSetOptions& options) {
    std::vector<std::string> written;
    try {
        return make_levels(input, requests, options, written);
    } catch (...) {
        // A set is written whole or not at all (each file is written atomically, so none is half-written).
        for (const std::string& file : written) {
            std::error_code ignored;
            std::filesystem::remove(file, ignored);
        }
        throw;
    }
}

}  // namespace rgbio
