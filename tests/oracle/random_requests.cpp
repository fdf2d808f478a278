#include "random_requests.h"

#include <glm/geometric.hpp>

namespace osdoracle {

std::vector<rgb::LevelRequest> random_requests(const FarInput& in, std::mt19937& rng, int count, int fixed_kind) {
    double edge = 0.0;
    for (const auto& t : in.triangles) edge += glm::distance(in.positions[t[0]], in.positions[t[1]]);
    edge /= static_cast<double>(in.triangles.size());
    auto uniform = [&] { return static_cast<double>(rng()) / 4294967296.0; };
    std::vector<rgb::LevelRequest> requests;
    for (int i = 0; i < count; ++i) {
        rgb::LevelRequest r;
        const int kind = fixed_kind >= 0 ? fixed_kind : static_cast<int>(rng() % 3);
        r.kind = kind == 0 ? rgb::RequestKind::Refine : kind == 1 ? rgb::RequestKind::Set : rgb::RequestKind::Coarsen;
        r.level = r.kind == rgb::RequestKind::Coarsen ? static_cast<int>(rng() % 3) : 1 + static_cast<int>(rng() % 3);
        const glm::dvec3 anchor = in.positions[rng() % in.positions.size()];
        r.sphere = rgb::Sphere{anchor + edge * glm::dvec3(uniform() - 0.5, uniform() - 0.5, uniform() - 0.5),
                               edge * (0.1 + 1.9 * uniform())};
        requests.push_back(r);
    }
    return requests;
}

}  // namespace osdoracle
