#include "app/auto_lod.h"

#include <algorithm>
#include <cstdint>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "rgb/lod/lod_driver.h"
#include "rgb/mesh/mesh.h"

namespace app {

namespace {

// Of the base mesh, so that the wanted length (and the result) does not depend on the current detail.
double bounding_box_diagonal(const rgb::BaseMesh& base) {
    glm::dvec3 lo(1e300), hi(-1e300);
    for (std::uint32_t v = 0; v < base.num_vertices(); ++v) {
        lo = glm::min(lo, base.position(v));
        hi = glm::max(hi, base.position(v));
    }
    return glm::distance(lo, hi);
}

rgb::LodSettings driver_settings(const rgb::Mesh& mesh, const AutoLodSettings& s) {
    rgb::LodSettings out;
    out.threshold = s.max_edge_fraction * bounding_box_diagonal(mesh.base());
    out.max_triangles = s.triangle_budget;
    return out;
}

}  // namespace

struct AutoLodJob::State {
    State(rgb::Mesh& m, const AutoLodSettings& s)
        : mesh(m), settings(s), start_faces(m.num_faces()), driver(m, driver_settings(m, s)) {}
    rgb::Mesh& mesh;
    AutoLodSettings settings;
    std::size_t start_faces;
    rgb::LodDriver driver;
};

AutoLodJob::AutoLodJob(rgb::Mesh& mesh, const AutoLodSettings& settings)
    : state_(std::make_unique<State>(mesh, settings)) {}

AutoLodJob::~AutoLodJob() = default;

bool AutoLodJob::step(std::chrono::microseconds slice) {
    State& s = *state_;
    const auto deadline = std::chrono::steady_clock::now() + slice;
    do {
        if (cancelled_) break;
        s.driver.run(64);
    } while (!s.driver.done() && std::chrono::steady_clock::now() < deadline);
    return !cancelled_ && !s.driver.done();
}

float AutoLodJob::progress() const {
    const State& s = *state_;
    if (s.driver.done()) return 1.0f;
    // The driver cannot know its remaining work; the distance to the budget is the honest proxy.
    const double from = static_cast<double>(s.start_faces), to = static_cast<double>(s.settings.triangle_budget);
    if (to == from) return 0.0f;
    const double done = (static_cast<double>(s.mesh.num_faces()) - from) / (to - from);
    return static_cast<float>(std::clamp(done, 0.0, 1.0));
}

bool AutoLodJob::changed() const {
    const rgb::LodReport& r = state_->driver.report();
    return r.splits + r.removals > 0;
}

}  // namespace app
