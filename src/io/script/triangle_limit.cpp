#include "io/script/triangle_limit.h"

#include <cmath>

#include <unistd.h>

#include "rgb/lod/requests.h"
#include "rgb/mesh/mesh.h"

namespace rgbio {

std::size_t default_triangle_limit() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
    if (pages <= 0 || page <= 0) return 100'000'000;
    return static_cast<std::size_t>(pages) * static_cast<std::size_t>(page) / kBytesPerTriangleBudget;
}

namespace {
void refuse(double estimate, std::size_t limit) {
    throw TooLarge("the request would make about " + std::to_string(static_cast<unsigned long long>(std::ceil(estimate))) +
                   " triangles, more than the limit of " + std::to_string(limit) +
                   " (set by this machine's memory; --max-triangles changes it)");
}
}  // namespace

void check_request_size(const rgb::Mesh& mesh, const rgb::LevelRequest& request, std::size_t limit) {
    const double estimate = rgb::estimated_triangles(mesh, request);
    if (estimate > static_cast<double>(limit)) refuse(estimate, limit);
}

void check_budget_size(std::size_t budget, std::size_t limit) {
    if (budget > limit) refuse(static_cast<double>(budget), limit);
}

}  // namespace rgbio
