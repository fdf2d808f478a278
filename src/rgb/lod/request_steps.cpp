#include "rgb/lod/request_steps.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rgb/lod/refine.h"
#include "rgb/mesh/mesh.h"

namespace rgb {

OperatorLog::OperatorLog(Mesh& mesh) : mesh_(mesh) { mesh_.add_observer(this); }

OperatorLog::~OperatorLog() { mesh_.remove_observer(this); }

void remove_finest_first(Mesh& mesh, std::vector<VertexId> doomed) {
    std::stable_sort(doomed.begin(), doomed.end(), [&](VertexId a, VertexId b) { return mesh.level(a) > mesh.level(b); });
    for (VertexId v : doomed)
        if (mesh.is_live(v)) remove_with_dependents(mesh, v);
}

std::vector<std::vector<VertexId>> vertices_above_by_level(const Mesh& mesh, int level) {
    std::vector<std::vector<VertexId>> by_level;
    for (VertexId v : mesh.vertices())
        if (mesh.level(v) > level) {
            const auto l = static_cast<std::size_t>(mesh.level(v));
            by_level.resize(std::max(by_level.size(), l + 1));
            by_level[l].push_back(v);
        }
    return by_level;
}

void check_sphere(const std::optional<Sphere>& sphere) {
    if (sphere && !(sphere->radius > 0.0 && std::isfinite(sphere->radius) && std::isfinite(sphere->centre.x) &&
                    std::isfinite(sphere->centre.y) && std::isfinite(sphere->centre.z)))
        throw std::invalid_argument("a request's sphere needs a finite centre and a positive radius");
}

}  // namespace rgb
