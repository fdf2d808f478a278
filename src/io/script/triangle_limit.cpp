#include "io/script/triangle_limit.h"

#include <algorithm>
#include <cmath>

#include <unistd.h>

#include "rgb/lod/lod_criteria.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/mesh.h"

namespace rgbio {

std::size_t bytes_per_triangle(MemoryUse use) {
    // The slopes tests/bench/memory_bench printed (docs/benchmarks.md, "Memory per triangle"; issue 30's
    // own figures where they were larger), a quarter more.
    switch (use) {
        case MemoryUse::Level: return 70;        // measured 53
        case MemoryUse::MaxEdge: return 210;     // 135, issue 30: 165
        case MemoryUse::Tolerance: return 3200;  // 2,549, issue 30: 1,420
        case MemoryUse::ScreenLod: return 550;   // 403, issue 30: 435
        case MemoryUse::Budget: return 160;      // 122
        case MemoryUse::Load: return 245;        // 195, issue 30: 169
        case MemoryUse::Remesh: return 490;      // 391 per detail point
        case MemoryUse::Editor: return 650;      // 515, opening saved files (edit --screenshot)
    }
    return bytes_per_triangle(MemoryUse::Tolerance);  // the dearest
}

namespace {
// Three quarters of the machine's physical memory over `cost` bytes a triangle.
std::size_t triangles_in_memory(std::size_t cost) {
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
    const double memory = pages > 0 && page > 0 ? 0.75 * double(pages) * double(page) : 16e9;
    return static_cast<std::size_t>(memory / double(cost));
}
}  // namespace

std::size_t default_triangle_limit(MemoryUse use) {
    std::size_t cost = bytes_per_triangle(use);
    if (use != MemoryUse::ScreenLod) cost = std::max(cost, bytes_per_triangle(MemoryUse::Load));
    return triangles_in_memory(cost);
}

std::size_t editor_triangle_limit(MemoryUse use) {
    return triangles_in_memory(std::max(bytes_per_triangle(use), bytes_per_triangle(MemoryUse::Editor)));
}

namespace {
void refuse(double estimate, std::size_t limit) {
    const std::string about = estimate < 1e18 ? std::to_string(static_cast<unsigned long long>(std::ceil(estimate)))
                                              : "more than 10^18";
    throw TooLarge("the request would make about " + about + " triangles, more than the limit of " + std::to_string(limit) +
                   " (set by this machine's memory; --max-triangles changes it)");
}
}  // namespace

void check_request_size(const rgb::Mesh& mesh, const rgb::LevelRequest& request, std::size_t limit) {
    const double estimate = rgb::estimated_triangles(mesh, request);
    if (estimate > static_cast<double>(limit)) refuse(estimate, limit);
}

void check_detail_size(const rgb::Mesh& mesh, const rgb::DetailRequest& request, std::size_t limit) {
    const double estimate = rgb::estimated_detail_triangles(mesh, request);
    if (estimate > static_cast<double>(limit)) refuse(estimate, limit);
}

void check_budget_size(std::size_t budget, std::size_t limit) {
    if (budget > limit) refuse(static_cast<double>(budget), limit);
}

}  // namespace rgbio
