#include "app/auto_lod.h"

#include <algorithm>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "rgb/lod_driver.h"
#include "rgb/loop_geometry.h"
#include "rgb/mesh.h"

namespace app {

namespace {

double bounding_box_diagonal(const rgb::Mesh& mesh) {
    glm::dvec3 lo(1e300), hi(-1e300);
    for (rgb::VertexId v : mesh.vertices()) {
        const glm::dvec3 p = rgb::displayed_position(mesh, v);
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return glm::distance(lo, hi);
}

rgb::LodSettings driver_settings(const rgb::Mesh& mesh, const AutoLodSettings& s) {
    const double wanted = s.max_edge_fraction * bounding_box_diagonal(mesh);
    rgb::LodSettings out;
    out.excess = rgb::edge_length_excess([wanted](const glm::dvec3&) { return wanted; });
    out.max_triangles = s.triangle_budget;
    out.max_level = s.max_level;
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

bool AutoLodJob::changed() const { return state_->driver.steps() > 0; }

}  // namespace app
