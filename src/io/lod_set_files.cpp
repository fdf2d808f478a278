#include "io/lod_set_files.h"

#include <atomic>
#include <filesystem>
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
    // Each level is a function of its request alone, so LOD0 is made (and written) on this thread
    // while the coarser levels, about a third of its work together, are made on another, in order.
    const std::size_t n = requests.size();
    std::vector<std::optional<LodSetLevel>> made(n);
    std::vector<GltfMesh> gltf(gltf_set ? n : 0);  // for a glTF set: the levels, written together at the end
    std::vector<std::string> files(n);             // the file each level was written to, or none
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
        const std::string file = lod_file_name(*options.output, i);
        if (format == OutputFormat::Obj) save_mesh(level.mesh, file, options.save);
        else save_export_mesh(flat, file, format, options.save.msh);
        files[i] = file;
    };
    // Told of the coarser levels once they are all made: a stop asked for then takes effect there.
    step(0);
    std::atomic<bool> lod0_failed = false;  // then the coarser levels are not wanted
    const auto collect_files = [&] {
        for (const std::string& file : files)
            if (!file.empty()) written.push_back(file);
    };
    try {
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
            });
    } catch (...) {
        collect_files();
        throw;
    }
    collect_files();
    for (std::size_t i = 0; i < n; ++i) {
        if (i > 0) step(i);
        set.levels.push_back(std::move(*made[i]));
        if (!gltf_set) continue;
        if (const std::optional<std::string> repair = gltf_normal_repair(gltf[i]))
            set.warnings.push_back("LOD" + std::to_string(i) + ": " + *repair);
    }
    for (std::size_t i = 1; i < set.levels.size(); ++i)
        set.levels[i].nested = positions_nested(set.levels[i].positions, set.levels[i - 1].positions);
    step(requests.size());
    std::vector<const rgb::Mesh*> measured;
    std::vector<std::vector<glm::dvec3>> corners;
    for (const LodSetLevel& level : set.levels) {
        measured.push_back(&level.mesh);
        corners.push_back(positions_by_slot(level.mesh, level.positions));
    }
    const std::vector<rgb::SurfaceError> errors = rgb::surface_errors_at(measured, corners);
    std::vector<double> error_values;
    for (std::size_t i = 0; i < set.levels.size(); ++i) error_values.push_back(set.levels[i].error = errors[i].max_error);
    const std::vector<double> coverage = switch_coverage(error_values, set.size);
    for (std::size_t i = 0; i < set.levels.size(); ++i) set.levels[i].coverage = coverage[i];
    if (gltf_set) save_gltf_lods(gltf, coverage, *options.output);
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
