// Reading one 1M-triangle mesh (a 1000 x 500 torus grid, 500,000 vertices) from OBJ, binary PLY
// (float and double positions) and glTF binary (float positions, uint32 indices), each the whole
// read `rgbsub info` does (read_mesh_file: parse, weld, validate). Issue 32's goal: glTF and binary
// PLY at most the time of the same mesh as OBJ. The positions are the floats glTF stores, so every
// file holds the same numbers. Files go to a folder under the system temp dir, removed at the end.
// Run on demand: ./format_load_bench
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include <unistd.h>

#include "../io/foreign_fixtures.h"
#include "io/mesh_reader.h"
#include "io/obj/number_format.h"

namespace {

namespace fs = std::filesystem;
using rgbio::test::put;

constexpr std::uint32_t kAround = 1000, kAcross = 500;  // 2 * 1000 * 500 = 1M triangles

struct Torus {
    std::vector<float> positions;  // xyz per vertex
    std::vector<std::uint32_t> triangles;
};

Torus make_torus() {
    Torus t;
    for (std::uint32_t i = 0; i < kAround; ++i)
        for (std::uint32_t j = 0; j < kAcross; ++j) {
            const double u = 2 * std::numbers::pi * i / kAround, v = 2 * std::numbers::pi * j / kAcross;
            const double r = 1.0 + 0.3 * std::cos(v);
            t.positions.insert(t.positions.end(), {static_cast<float>(r * std::cos(u)), static_cast<float>(r * std::sin(u)), static_cast<float>(0.3 * std::sin(v))});
        }
    const auto at = [](std::uint32_t i, std::uint32_t j) { return (i % kAround) * kAcross + j % kAcross; };
    for (std::uint32_t i = 0; i < kAround; ++i)
        for (std::uint32_t j = 0; j < kAcross; ++j)
            t.triangles.insert(t.triangles.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    return t;
}

std::string obj_text(const Torus& t) {
    std::string out;
    for (std::size_t v = 0; v < t.positions.size(); v += 3) {
        out += 'v';
        for (int c = 0; c < 3; ++c) rgbio::append_double(out, t.positions[v + static_cast<std::size_t>(c)]);
        out += '\n';
    }
    for (std::size_t f = 0; f < t.triangles.size(); f += 3) {
        out += 'f';
        for (int c = 0; c < 3; ++c) rgbio::append_integer(out, std::uint64_t(t.triangles[f + static_cast<std::size_t>(c)]) + 1);
        out += '\n';
    }
    return out;
}

std::string ply_binary(const Torus& t, bool doubles) {
    std::string out = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(t.positions.size() / 3) + "\n";
    for (const char* axis : {"x", "y", "z"}) out += std::string("property ") + (doubles ? "double " : "float ") + axis + "\n";
    out += "element face " + std::to_string(t.triangles.size() / 3) + "\nproperty list uchar uint vertex_indices\nend_header\n";
    for (float x : t.positions) doubles ? put<double>(out, x) : put<float>(out, x);
    for (std::size_t f = 0; f < t.triangles.size(); f += 3) {
        put<std::uint8_t>(out, 3);
        for (int c = 0; c < 3; ++c) put<std::uint32_t>(out, t.triangles[f + static_cast<std::size_t>(c)]);
    }
    return out;
}

std::string glb(const Torus& t) {
    std::string bin;
    for (float x : t.positions) put<float>(bin, x);
    for (std::uint32_t i : t.triangles) put<std::uint32_t>(bin, i);
    const std::size_t p = t.positions.size() * 4, i = t.triangles.size() * 4;
    const std::string json = R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],"buffers":[{"byteLength":)" +
                             std::to_string(p + i) + R"(}],"bufferViews":[{"buffer":0,"byteLength":)" + std::to_string(p) +
                             R"(},{"buffer":0,"byteOffset":)" + std::to_string(p) + R"(,"byteLength":)" + std::to_string(i) +
                             R"(}],"accessors":[{"bufferView":0,"componentType":5126,"count":)" + std::to_string(t.positions.size() / 3) +
                             R"(,"type":"VEC3"},{"bufferView":1,"componentType":5125,"count":)" + std::to_string(t.triangles.size()) +
                             R"(,"type":"SCALAR"}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}]})";
    return rgbio::test::glb_file(json, bin);
}

// The four files, written once for all the benchmarks.
struct Files {
    fs::path folder = fs::temp_directory_path() / ("rgbsub_format_load_bench_" + std::to_string(::getpid()));
    Files() {
        fs::create_directories(folder);
        const Torus t = make_torus();
        std::ofstream(folder / "torus.obj", std::ios::binary) << obj_text(t);
        std::ofstream(folder / "torus_float.ply", std::ios::binary) << ply_binary(t, false);
        std::ofstream(folder / "torus_double.ply", std::ios::binary) << ply_binary(t, true);
        std::ofstream(folder / "torus.glb", std::ios::binary) << glb(t);
    }
    ~Files() { fs::remove_all(folder); }
};

const Files& files() {
    static const Files instance;
    return instance;
}

void read(benchmark::State& state, const char* name) {
    const std::string path = (files().folder / name).string();
    for (auto _ : state) {
        const rgbio::LoadedMesh mesh = rgbio::read_mesh_file(path);
        if (mesh.triangles.size() != 2u * kAround * kAcross) state.SkipWithError("wrong triangle count");
    }
    state.counters["MB"] = static_cast<double>(fs::file_size(path)) / 1e6;
}

void BM_ReadObj(benchmark::State& state) { read(state, "torus.obj"); }
void BM_ReadPlyFloat(benchmark::State& state) { read(state, "torus_float.ply"); }
void BM_ReadPlyDouble(benchmark::State& state) { read(state, "torus_double.ply"); }
void BM_ReadGlb(benchmark::State& state) { read(state, "torus.glb"); }

BENCHMARK(BM_ReadObj)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_ReadPlyFloat)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_ReadPlyDouble)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_ReadGlb)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
