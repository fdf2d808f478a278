// Headless renderer benchmarks (OSMesa/llvmpipe, 1024x768): frames per second for 100k and 1M
// triangles, and brush-like edits followed by a frame with incremental versus full re-upload.
// Run on demand: ./render_bench (real time: llvmpipe renders on worker threads).
#include <benchmark/benchmark.h>
#include <glad/gl.h>

#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include "render/headless.h"
#include "render/offscreen_context.h"
#include "render/renderer.h"
#include "rgb/lod/refine.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/loop_geometry.h"

namespace {

constexpr glm::ivec2 kViewport{1024, 768};

// A closed torus of 2 * rings * segments triangles.
rgb::Mesh torus(int rings, int segments) {
    std::vector<glm::dvec3> points;
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const double u = 2 * std::numbers::pi * i / rings, v = 2 * std::numbers::pi * j / segments;
            points.emplace_back((1.0 + 0.4 * std::cos(v)) * std::cos(u), 0.4 * std::sin(v), (1.0 + 0.4 * std::cos(v)) * std::sin(u));
        }
    std::vector<rgb::Triangle> triangles;
    const auto id = [&](int i, int j) { return static_cast<std::uint32_t>((i % rings) * segments + j % segments); };
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
            triangles.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
        }
    return rgb::Mesh(points, triangles);
}

// Built once per size: a 1M-triangle mesh takes seconds to construct.
rgb::Mesh& mesh_with_triangles(long triangles) {
    static std::map<long, std::unique_ptr<rgb::Mesh>> cache;
    auto& slot = cache[triangles];
    if (!slot) {
        const int segments = triangles >= 1000000 ? 500 : 200;
        slot = std::make_unique<rgb::Mesh>(torus(static_cast<int>(triangles / (2 * segments)), segments));
    }
    return *slot;
}

render::RenderOptions options_for(long mode) {
    render::RenderOptions options;
    if (mode == 1) options.wireframe = true;
    if (mode == 2) {
        options.shading = render::Shading::Flat;
        options.colouring = render::Colouring::RgbType;
        options.wireframe = true;
    }
    return options;
}

// Args: triangles, mode (0 smooth shaded, 1 shaded + wireframe, 2 RGB types + wireframe).
void BM_Frame(benchmark::State& state) {
    rgb::Mesh& mesh = mesh_with_triangles(state.range(0));
    render::OffscreenContext context(kViewport.x, kViewport.y);
    render::Renderer renderer;
    renderer.attach(mesh);
    const render::OrbitCamera camera = render::framing_camera(renderer.bounds(), {kViewport, 30.0f, 35.0f});
    const render::RenderOptions options = options_for(state.range(1));
    renderer.draw(camera, options, kViewport);  // shader JIT
    for (auto _ : state) {
        renderer.draw(camera, options, kViewport);
        glFinish();
    }
    state.counters["triangles"] = static_cast<double>(mesh.num_faces());
    state.counters["fps"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Frame)
    ->ArgNames({"triangles", "mode"})
    ->ArgsProduct({{100000, 1000000}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Brush-like edits of radius 0.05 (about two base edges of the torus) that leave the mesh as they
// found it in pairs: refine to level 2 around a random point, then coarsen that spot back to level 0.
class Dabs {
public:
    void next(rgb::Mesh& mesh) {
        if (refine_) {
            rgb::FaceId seed;
            do seed = rgb::FaceId(static_cast<std::uint32_t>(random_() % mesh.face_capacity()));
            while (!mesh.is_live(seed));
            centre_ = mesh.base_space_position(mesh.face_vertices(seed)[0]);
        }
        rgb::LevelRequest request;
        request.level = refine_ ? 2 : 0;
        request.sphere = rgb::Sphere{centre_, 0.05};
        rgb::apply_request(mesh, request);
        refine_ = !refine_;
    }

private:
    std::mt19937 random_{12345};
    glm::dvec3 centre_{0.0};
    bool refine_ = true;
};

// Dabs on the 100k torus (not timed), each followed by the
// upload (changed slots only, or everything) and, with `frame`, a 1024x768 frame.
void BM_Edit(benchmark::State& state) {
    const bool full = state.range(0) == 1;
    const bool frame = state.range(1) == 1;
    rgb::Mesh mesh = torus(250, 200);
    render::OffscreenContext context(kViewport.x, kViewport.y);
    render::Renderer renderer;
    renderer.attach(mesh);
    const render::OrbitCamera camera = render::framing_camera(renderer.bounds(), {kViewport, 30.0f, 35.0f});
    const render::RenderOptions options = options_for(0);
    renderer.draw(camera, options, kViewport);
    Dabs dabs;
    std::uint64_t bytes = 0;
    std::int64_t edits = 0;
    for (auto _ : state) {
        state.PauseTiming();
        dabs.next(mesh);
        const std::uint64_t before = renderer.upload_stats().total_bytes;
        state.ResumeTiming();

        if (full)
            renderer.reupload_all();
        else
            renderer.sync();
        if (frame) renderer.draw(camera, options, kViewport);
        glFinish();

        bytes += renderer.upload_stats().total_bytes - before;
        ++edits;
    }
    state.counters["bytes_per_edit"] = static_cast<double>(bytes) / static_cast<double>(edits);
    state.counters["triangles"] = static_cast<double>(mesh.num_faces());
}
BENCHMARK(BM_Edit)
    ->ArgNames({"full_reupload", "frame"})
    ->ArgsProduct({{0, 1}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
