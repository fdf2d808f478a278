// Core benchmark (run on demand, not part of ctest): uniform refinement of assets/bunny.obj to levels
// 3, 4, 5 through the RGB operators, side by side with OpenMesh's LoopT on the same input in the same
// process; edge splits and vertex removals per second; bytes per triangle of the core mesh against a
// plain indexed double mesh (24 bytes per vertex + 12 per triangle).
#include <chrono>

#include <benchmark/benchmark.h>

#include "rgb/lod/refine.h"
#include "support/openmesh_loop.h"
#include "support/random_operations.h"
#include "support/test_meshes.h"

namespace {

using Clock = std::chrono::steady_clock;

const rgbtest::TestMesh& bunny() {
    static const rgbtest::TestMesh mesh = rgbtest::bunny();
    return mesh;
}

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Each iteration subdivides fresh copies of the bunny with both implementations; only the
// subdivision itself is on the clock, conversions and copies are not.
void BM_UniformRgbVsOpenMesh(benchmark::State& state) {
    const int level = static_cast<int>(state.range(0));
    double rgb_seconds = 0, openmesh_seconds = 0;
    std::size_t splits = 0, faces = 0, core_bytes = 0, plain_bytes = 0;
    for (auto _ : state) {
        rgb::Mesh mesh = rgbtest::make_rgb_mesh(bunny());
        const std::size_t base_vertices = mesh.num_vertices();
        Clock::time_point start = Clock::now();
        rgb::refine_uniform(mesh, level);
        rgb_seconds += seconds_since(start);
        splits = mesh.num_vertices() - base_vertices;
        faces = mesh.num_faces();
        core_bytes = mesh.memory_bytes();
        plain_bytes = 24 * mesh.num_vertices() + 12 * mesh.num_faces();

        rgbtest::OpenMeshLoop reference(bunny());
        start = Clock::now();
        reference.subdivide(level);
        openmesh_seconds += seconds_since(start);
        benchmark::DoNotOptimize(reference.num_faces());
    }
    const double n = static_cast<double>(state.iterations());
    state.counters["rgb_ms"] = 1e3 * rgb_seconds / n;
    state.counters["openmesh_ms"] = 1e3 * openmesh_seconds / n;
    state.counters["rgb/openmesh"] = rgb_seconds / openmesh_seconds;
    state.counters["splits_per_s"] = static_cast<double>(splits) * n / rgb_seconds;
    state.counters["triangles"] = static_cast<double>(faces);
    state.counters["core_B_per_tri"] = static_cast<double>(core_bytes) / static_cast<double>(faces);
    state.counters["plain_B_per_tri"] = static_cast<double>(plain_bytes) / static_cast<double>(faces);
    state.counters["memory_ratio"] = static_cast<double>(core_bytes) / static_cast<double>(plain_bytes);
}
BENCHMARK(BM_UniformRgbVsOpenMesh)->Arg(3)->Iterations(10)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_UniformRgbVsOpenMesh)->Arg(4)->Iterations(4)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_UniformRgbVsOpenMesh)->Arg(5)->Iterations(2)->Unit(benchmark::kMillisecond);

// Removes every removable vertex of the uniformly refined bunny (with the swaps and merges each
// removal needs) until the base mesh is back.
void BM_RemoveToBase(benchmark::State& state) {
    const int level = static_cast<int>(state.range(0));
    double seconds = 0;
    std::size_t removals = 0;
    for (auto _ : state) {
        rgb::Mesh mesh = rgbtest::make_rgb_mesh(bunny());
        rgb::refine_uniform(mesh, level);
        const Clock::time_point start = Clock::now();
        removals = rgbtest::remove_everything_removable(mesh);
        seconds += seconds_since(start);
        if (mesh.num_faces() != bunny().triangles.size()) state.SkipWithError("did not coarsen back to the base mesh");
    }
    state.counters["removals"] = static_cast<double>(removals);
    state.counters["removals_per_s"] = static_cast<double>(removals) * static_cast<double>(state.iterations()) / seconds;
}
BENCHMARK(BM_RemoveToBase)->Arg(3)->Iterations(5)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RemoveToBase)->Arg(4)->Iterations(2)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
