// Dense-surface benchmark: the search tree's build and the three batch queries of
// src/detail/dense_surface.h (rays, closest points, projections) on a torus of a million triangles,
// a million queries each on all cores, as `remesh` asks them (limit points near M along rough
// normals, one in ten far off). Prints the processor and the rates; asserts nothing but that most
// rays hit (tests/detail/dense_surface_test.cpp checks the answers against brute force).
// Run on demand: ./dense_surface_bench [--smoke] (--smoke: 10,000 triangles and queries, for CI).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>

#include "detail/dense_surface.h"

namespace {

constexpr double kBig = 1.0, kSmall = 0.35;

glm::dvec3 torus_point(double u, double v) {
    return {(kBig + kSmall * std::cos(v)) * std::cos(u), (kBig + kSmall * std::cos(v)) * std::sin(u), kSmall * std::sin(v)};
}
glm::dvec3 torus_normal(double u, double v) { return {std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v)}; }

// A grid of nu x nv quads around the torus, two triangles each.
rgbdetail::DenseSurface torus_surface(int nu, int nv) {
    std::vector<glm::dvec3> positions;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j)
            positions.push_back(torus_point(2 * std::numbers::pi * i / nu, 2 * std::numbers::pi * j / nv));
    auto at = [&](int i, int j) { return static_cast<std::uint32_t>((i % nu) * nv + (j % nv)); };
    std::vector<rgb::Triangle> triangles;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return rgbdetail::DenseSurface(std::move(positions), std::move(triangles));
}

std::string processor_name() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) {
            const std::size_t colon = line.find(':');
            return colon == std::string::npos ? line : line.substr(colon + 2);
        }
    return "unknown processor";
}

template <class Work>
double seconds_of(const Work& work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
    const bool smoke = argc > 1 && std::string_view(argv[1]) == "--smoke";
    const int nu = smoke ? 100 : 1000, nv = smoke ? 50 : 500;
    const std::size_t n = 2 * static_cast<std::size_t>(nu) * static_cast<std::size_t>(nv);

    std::optional<rgbdetail::DenseSurface> surface;
    const double build = seconds_of([&] { surface.emplace(torus_surface(nu, nv)); });

    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto random_unit = [&] {
        const double z = 2 * unit(rng) - 1, a = 2 * std::numbers::pi * unit(rng), r = std::sqrt(1 - z * z);
        return glm::dvec3(r * std::cos(a), r * std::sin(a), z);
    };
    std::vector<glm::dvec3> origins(n), directions(n), points(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double u = 2 * std::numbers::pi * unit(rng), v = 2 * std::numbers::pi * unit(rng);
        const glm::dvec3 normal = torus_normal(u, v);
        const double offset = (i % 10 == 0 ? 0.5 : 0.02) * (2 * unit(rng) - 1);
        origins[i] = torus_point(u, v) + offset * normal;
        directions[i] = glm::normalize(normal + 0.1 * random_unit());
        points[i] = torus_point(u, v) + 0.05 * (2 * unit(rng) - 1) * normal + 0.01 * random_unit();
    }
    const double max_distance = 0.05;
    std::size_t found = 0;
    const double rays = seconds_of([&] {
        const auto hits = surface->nearest_ray_hits(origins, directions, max_distance);
        found = static_cast<std::size_t>(std::count_if(hits.begin(), hits.end(), [](const auto& h) { return h.has_value(); }));
    });
    const double closest = seconds_of([&] { (void)surface->closest_points(points); });
    const double projections = seconds_of([&] { (void)surface->projections(origins, directions, max_distance); });

    std::printf("processor: %s, %u hardware threads\n", processor_name().c_str(), std::thread::hardware_concurrency());
    std::printf("build of %zu triangles: %.3f s\n", n, build);
    std::printf("nearest_ray_hits: %zu lines (%zu hit, search distance %g): %.3f s, %.0f per s\n", n, found,
                max_distance, rays, static_cast<double>(n) / rays);
    std::printf("closest_points: %zu points: %.3f s, %.0f per s\n", n, closest, static_cast<double>(n) / closest);
    std::printf("projections (ray, else closest point): %zu: %.3f s, %.0f per s\n", n, projections,
                static_cast<double>(n) / projections);
    if (found <= n / 2) {
        std::fprintf(stderr, "dense_surface_bench: only %zu of %zu rays hit the torus\n", found, n);
        return 1;
    }
    return 0;
}
