// Criteria benchmark (docs/benchmarks.md): what the tolerance criterion saves and what it costs, and
// how the view-dependent updater behaves along an orbit.
//  1. For each mesh and tolerance (a share of the bounding-box diagonal): the triangles and time of
//     the tolerance request over the whole surface, with the largest error reached, against uniform
//     Loop at the first level whose displayed surface meets the same tolerance (by the same measure,
//     rgb::displayed_surface_error); uniform levels stop at --uniform-cap triangles.
//  2. View-dependent LOD on the bunny: converge for a first view, then orbit in 5-degree steps with
//     one update of --slice milliseconds per frame; per-frame engine time p50/p95, triangles, and
//     how many frames the updater needs to settle after the camera stops.
// Run on demand: ./criteria_bench [--pixels PX] [--slice MS] [--uniform-cap TRIANGLES] [--tolerances 1,0.3,...]
//                                 [--only tolerance|orbit]
// Builds the meshes it needs from the source tree's assets and test fixtures.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "frame_timing.h"
#include "io/mesh_file.h"
#include "io/script/detail_edit.h"
#include "render/camera.h"
#include "rgb/lod/refine.h"
#include "rgb/lod/requests.h"
#include "rgb/lod/view_lod.h"
#include "rgb/mesh/base_mesh.h"
#include "rgb/values/surface_error.h"

namespace {

using bench::percentile;
using bench::thread_cpu_ms;

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

struct Options {
    double pixels = 3.0;
    double slice_ms = 8.0;
    std::size_t uniform_cap = 1'000'000;
    std::vector<double> tolerances_percent{1.0, 0.3, 0.1};
    bool tolerance_part = true, orbit_part = true;
};

Options parse(int argc, char** argv) {
    Options options;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string name = argv[i];
        const char* value = argv[i + 1];
        if (name == "--pixels") options.pixels = std::atof(value);
        else if (name == "--slice") options.slice_ms = std::atof(value);
        else if (name == "--only") {
            options.tolerance_part = std::string(value) == "tolerance";
            options.orbit_part = std::string(value) == "orbit";
        } else if (name == "--uniform-cap") options.uniform_cap = static_cast<std::size_t>(std::atoll(value));
        else if (name == "--tolerances") {
            options.tolerances_percent.clear();
            for (const char* p = value; *p;) {
                char* end = nullptr;
                const double percent = std::strtod(p, &end);
                if (end == p || !(percent > 0.0)) {
                    std::fprintf(stderr, "criteria_bench: --tolerances expects positive numbers separated by commas\n");
                    std::exit(2);
                }
                options.tolerances_percent.push_back(percent);
                p = *end == ',' ? end + 1 : end;
            }
        } else {
            std::fprintf(stderr, "criteria_bench: unknown option %s\n", name.c_str());
            std::exit(2);
        }
    }
    return options;
}

struct UniformLevel {
    int level;
    std::size_t triangles;
    double error;
};

// Uniform Loop level by level, from the base mesh until the next level would pass the cap.
std::vector<UniformLevel> uniform_errors(const std::string& path, std::size_t cap) {
    std::vector<UniformLevel> levels;
    rgb::Mesh mesh = rgbio::load_mesh(path);
    for (int level = 0; level <= rgb::kMaxLevel; ++level) {
        if (level > 0) rgb::refine_uniform(mesh, level);
        levels.push_back({level, mesh.num_faces(), rgb::displayed_surface_error(mesh).max_error});
        if (mesh.num_faces() * 4 > cap) break;
    }
    return levels;
}

void tolerance_table(const std::vector<std::string>& paths, const Options& options) {
    std::printf("| mesh | tolerance (%% of diagonal) | RGB triangles | error reached | time | uniform Loop level: triangles (error) | ratio |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    for (const std::string& path : paths) {
        const std::string name = path.substr(path.find_last_of('/') + 1);
        const std::vector<UniformLevel> uniform = uniform_errors(path, options.uniform_cap);
        for (double percent : options.tolerances_percent) {
            rgb::Mesh mesh = rgbio::load_mesh(path);
            rgbio::DetailEdit edit;
            edit.criterion = rgbio::DetailCriterion::Tolerance;
            edit.amount = {percent, true};
            const double tolerance = rgbio::world_amount(mesh, edit.amount);
            const auto start = Clock::now();
            const rgbio::DetailOutcome outcome = rgbio::apply_detail_edit(mesh, edit, 50'000'000);
            const double time = seconds_since(start);
            const auto met = std::find_if(uniform.begin(), uniform.end(), [&](const UniformLevel& u) { return u.error <= tolerance; });
            // Past the measured levels the first level that meets it has at least 4x the last's triangles.
            const bool measured = met != uniform.end();
            const UniformLevel& reached = measured ? *met : uniform.back();
            const std::size_t uniform_triangles = measured ? reached.triangles : 4 * reached.triangles;
            char reference[128], ratio[32];
            if (measured) std::snprintf(reference, sizeof reference, "%d: %zu (%.3g)", reached.level, reached.triangles, reached.error);
            else std::snprintf(reference, sizeof reference, ">= %d: >= %zu (level %d: %.3g)", reached.level + 1, uniform_triangles, reached.level, reached.error);
            std::snprintf(ratio, sizeof ratio, "%s%.2f", measured ? "" : ">= ", static_cast<double>(uniform_triangles) / static_cast<double>(mesh.num_faces()));
            std::printf("| %s | %g | %zu | %.3g (tolerance %.3g) | %.2f s | %s | %s |\n", name.c_str(), percent, mesh.num_faces(),
                        outcome.reached_error.value_or(-1.0), tolerance, time, reference, ratio);
            std::fflush(stdout);
        }
    }
}

void orbit(const std::string& path, const Options& options) {
    rgb::Mesh mesh = rgbio::load_mesh(path);
    const glm::ivec2 size(1920, 1080);
    std::vector<glm::vec3> points;
    for (std::uint32_t v = 0; v < mesh.base().num_vertices(); ++v) points.push_back(glm::vec3(mesh.base().position(v)));
    const render::BoundingSphere bounds = render::bounding_sphere(points);
    const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
    render::OrbitCamera camera = render::frame_sphere(bounds, 0.0f, 20.0f, aspect);

    rgb::ViewLodSettings settings;
    settings.pixels = options.pixels;
    settings.max_triangles = 8'000'000;
    rgb::ViewLod lod(mesh, settings, render::screen_view(camera, size));
    auto start = Clock::now();
    while (!lod.update(std::chrono::seconds(10))) {
    }
    std::printf("\nview-dependent LOD, %s at %dx%d, %g px: first view settled in %.2f s, %zu triangles\n", path.substr(path.find_last_of('/') + 1).c_str(),
                size.x, size.y, options.pixels, seconds_since(start), mesh.num_faces());

    const auto slice = std::chrono::microseconds(static_cast<long>(options.slice_ms * 1000.0));
    std::vector<double> frame_ms, frame_cpu_ms;
    std::size_t most = 0, fewest = mesh.num_faces();
    for (int step = 1; step <= 72; ++step) {
        camera.azimuth_deg = 5.0f * static_cast<float>(step);
        lod.set_view(render::screen_view(camera, size));
        start = Clock::now();
        const double cpu = thread_cpu_ms();
        lod.update(slice);
        frame_ms.push_back(1000.0 * seconds_since(start));
        frame_cpu_ms.push_back(thread_cpu_ms() - cpu);
        most = std::max(most, mesh.num_faces());
        fewest = std::min(fewest, mesh.num_faces());
    }
    std::printf("orbit, 72 frames of 5 degrees, %.1f ms slice: engine per frame p50 %.2f ms, p95 %.2f ms (processor time p50 %.2f, p95 %.2f ms); "
                "%zu to %zu triangles\n",
                options.slice_ms, percentile(frame_ms, 0.5), percentile(frame_ms, 0.95), percentile(frame_cpu_ms, 0.5),
                percentile(frame_cpu_ms, 0.95), fewest, most);
    int frames = 0;
    start = Clock::now();
    while (!lod.update(slice)) ++frames;
    std::printf("camera stopped: settled after %d more frames (%.2f s), %zu triangles; splits %zu, removals %zu in all\n", frames + 1,
                seconds_since(start), mesh.num_faces(), lod.stats().splits, lod.stats().removals);
}

}  // namespace

int main(int argc, char** argv) {
    const Options options = parse(argc, argv);
    const std::string source = RGBSUB_SOURCE_DIR;
    const std::vector<std::string> meshes{source + "/tests/render/fixtures/octahedron.obj", source + "/tests/io/fuzz/seeds/cube_quads.obj",
                                          source + "/assets/default.obj", source + "/assets/bunny.obj"};
    if (options.tolerance_part) tolerance_table(meshes, options);
    if (options.orbit_part) orbit(source + "/assets/bunny.obj", options);
    return 0;
}
