// Loader benchmarks: ear clipping of single polygons with 200,000 corners (convex, star, comb,
// winding strip) and `rgbsub info`'s whole read of such a polygon from OBJ text. Issue 11 item 10
// measured 119 s for that read before triangulation became near-linear.
// Run on demand: ./obj_load_bench
#include <benchmark/benchmark.h>

#include <numeric>
#include <string>
#include <vector>

#include "../io/polygon_shapes.h"
#include "io/obj/number_format.h"
#include "io/obj_reader.h"
#include "io/repair/polygon_triangulation.h"

namespace {

constexpr int kCorners = 200'000;

void triangulate(benchmark::State& state, const std::vector<glm::dvec3>& polygon_points) {
    std::vector<std::uint32_t> polygon(polygon_points.size());
    std::iota(polygon.begin(), polygon.end(), 0u);
    for (auto _ : state) benchmark::DoNotOptimize(rgbio::triangulate_polygon_corners(polygon_points, polygon));
    state.counters["corners"] = static_cast<double>(polygon.size());
}

void BM_TriangulateCircle(benchmark::State& state) { triangulate(state, rgbio::test::circle_polygon(kCorners)); }
void BM_TriangulateStar(benchmark::State& state) { triangulate(state, rgbio::test::star_polygon(kCorners / 2)); }
void BM_TriangulateComb(benchmark::State& state) { triangulate(state, rgbio::test::comb_polygon(kCorners / 4)); }
void BM_TriangulateSpiral(benchmark::State& state) { triangulate(state, rgbio::test::spiral_polygon(kCorners)); }

// The whole loader on one `f` line of 200,000 corners, as `rgbsub info` reads it.
void BM_ReadCirclePolygonFile(benchmark::State& state) {
    std::string text;
    for (const glm::dvec3& p : rgbio::test::circle_polygon(kCorners)) {
        text += 'v';
        for (int i = 0; i < 3; ++i) rgbio::append_double(text, p[i]);
        text += '\n';
    }
    text += 'f';
    for (int i = 1; i <= kCorners; ++i) text += ' ' + std::to_string(i);
    text += '\n';
    for (auto _ : state) benchmark::DoNotOptimize(rgbio::read_obj_text(text, "circle.obj"));
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}

BENCHMARK(BM_TriangulateCircle)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TriangulateStar)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TriangulateComb)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TriangulateSpiral)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadCirclePolygonFile)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
