// rgbsub remesh IN -o OUT.obj --cage-triangles N [--cage CAGE.obj]: a dense mesh in, a cage with
// its detail out (src/detail/remesh.h), saved as an adaptive OBJ that resumes without IN.
#include <iostream>
#include <optional>
#include <stdexcept>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/mesh_io_support.h"
#include "cli/progress.h"
#include "detail/remesh.h"
#include "io/files/save_target.h"
#include "io/mesh_file.h"
#include "io/script/triangle_limit.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/loop_geometry.h"

namespace cli {

namespace {

// The mesh as it is displayed: compacted positions and triangles.
struct PlainMesh {
    std::vector<glm::dvec3> positions;
    std::vector<rgb::Triangle> triangles;
};

PlainMesh displayed_mesh(const rgb::Mesh& mesh) {
    PlainMesh plain;
    std::vector<std::uint32_t> index(mesh.vertex_capacity(), 0);
    for (rgb::VertexId v : mesh.vertices()) {
        index[v.idx] = static_cast<std::uint32_t>(plain.positions.size());
        plain.positions.push_back(rgb::displayed_position(mesh, v));
    }
    for (rgb::FaceId f : mesh.faces()) {
        const auto& c = mesh.face_vertices(f);
        plain.triangles.push_back({index[c[0].idx], index[c[1].idx], index[c[2].idx]});
    }
    return plain;
}

// What the file carries besides geometry, which a remesh does not carry across yet (one warning).
void warn_dropped(const std::string& file, const rgbio::LoadedAsset& asset) {
    std::vector<std::string> dropped;
    if (asset.attributes) {
        for (const std::string& what : rgbio::dropped_attributes(asset.mesh, asset.attributes.get(), false)) dropped.push_back(what);
    }
    if (!dropped.empty()) print_warnings("remesh", file, {"remesh keeps the geometry only; dropped: " + dropped.front()});
}

}  // namespace

int run_remesh(std::span<const std::string> args) {
    const Arguments arguments(args, {kStrictSwitch, "--timings"}, {"--output", "--cage-triangles", "--cage", "--max-triangles", kSharpAngleOption},
                              {{"-o", "--output"}});
    if (arguments.has("--help")) {
        std::cout << "usage: rgbsub remesh IN.obj -o OUT.obj --cage-triangles N [--cage CAGE.obj] [--max-triangles N]\n"
                     "                     [--strict] [--sharp-angle DEG] [--timings]\n"
                     "Makes a coarse cage of a dense mesh and keeps the dense mesh's detail: the cage (IN decimated to\n"
                     "at most N and at least about N/3 triangles, with IN's topology; or CAGE.obj, which must have it)\n"
                     "is fitted so that its Loop limit surface approximates IN, and every vertex of every level of\n"
                     "detail over it, up to the level as dense as IN, is put on IN: where the line along the limit\n"
                     "normal meets IN, else IN's nearest point. OUT.obj is the cage with its detail; refine, apply,\n"
                     "render, info and the editor work on it like on any saved file, without IN.\n"
                  << kStrictHelp
                  << "  --sharp-angle DEG   tag the cage's edges sharper than DEG as creases before the fit, which\n"
                     "                      then places the creased limit surface; OUT.obj keeps the tags\n";
        return exit_ok;
    }
    if (arguments.positional().size() != 1) throw UsageError("expects exactly one IN.obj");
    const std::optional<std::string> output = arguments.value("--output");
    if (!output) throw UsageError("needs -o OUT.obj");
    if (!rgbio::has_extension(*output, ".obj")) throw UsageError("writes an OBJ (OUT.obj): the detail lives in its state");
    const bool given_cage = arguments.has("--cage");
    if (!given_cage && !arguments.has("--cage-triangles")) throw UsageError("needs --cage-triangles N (or --cage CAGE.obj)");
    const auto limit = static_cast<std::size_t>(
        arguments.integer("--max-triangles", static_cast<long>(rgbio::default_triangle_limit(rgbio::MemoryUse::Remesh)), 1, 4'000'000'000l));
    const std::string& input = arguments.positional()[0];

    rgbdetail::RemeshOptions options;
    options.source_name = input;
    if (!given_cage) {
        options.cage_triangles = static_cast<std::size_t>(arguments.integer("--cage-triangles", 0, 1, 4'000'000'000l));
        if (options.cage_triangles > limit)
            throw rgbio::TooLarge("a cage of " + std::to_string(options.cage_triangles) + " triangles is over --max-triangles " +
                                  std::to_string(limit));
    }
    check_output_first(*output);
    const rgbio::LoadedAsset asset = load_input("remesh", input, arguments);
    check_gltf_output_first("remesh", *output, asset);
    warn_dropped(input, asset);
    const PlainMesh dense = displayed_mesh(asset.mesh);
    // load_input has checked the angle's range. The cage is tagged, and fitted with the tags, inside
    // remesh: the cage it makes exists only there.
    options.check_points = [limit](std::size_t points) {
        if (points > limit)
            throw rgbio::TooLarge("the detail would hold " + std::to_string(points) + " points, more than the limit of " + std::to_string(limit) +
                                  " (set by this machine's memory; --max-triangles changes it)");
    };
    if (arguments.has(kSharpAngleOption)) options.sharp_angle = arguments.number(kSharpAngleOption, 0.0);
    if (given_cage) {
        const rgbio::LoadedAsset cage = load_input("remesh", *arguments.value("--cage"), arguments);
        PlainMesh plain = displayed_mesh(cage.mesh);
        options.cage_positions = std::move(plain.positions);
        options.cage_triangles_given = std::move(plain.triangles);
    }
    rgbdetail::Remeshed remeshed;
    {
        Progress progress("remeshing");
        options.progress = [&progress](double share, const char* phase) {
            progress.update(static_cast<std::size_t>(1000 * share), 1000, phase);
            return true;
        };
        try {
            remeshed = rgbdetail::remesh(dense.positions, dense.triangles, options);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument(input + ": " + e.what());
        }
    }
    const rgb::Mesh mesh(remeshed.base);
    const rgbdetail::RemeshReport& r = remeshed.report;
    std::cout << "rgbsub remesh: cage of " << r.cage_triangles << " triangles, fitted: distance to the mesh rms " << r.fit_before.rms
              << " -> " << r.fit_after.rms << ", max " << r.fit_before.max << " -> " << r.fit_after.max << '\n'
              << "rgbsub remesh: detail to level " << r.detail_level;
    if (r.finest_detail_level > r.detail_level) std::cout << ".." << r.finest_detail_level << " (each cage face as dense as the mesh over it)";
    std::cout << ", " << r.detail_points << " points, ";
    if (r.feature_points > 0) std::cout << r.feature_points << " on the mesh's sharp features, ";
    std::cout << r.nearest_points << " on the nearest point (no ray hit within " << r.search_distance << ")\n";
    if (arguments.has("--timings"))
        std::cout << "rgbsub remesh: seconds: cage " << r.seconds_cage << ", fit " << r.seconds_fit << ", detail " << r.seconds_detail << '\n';
    rgbio::SaveOptions save;
    save_output("remesh", mesh, *output, save);
    return exit_ok;
}

}  // namespace cli
