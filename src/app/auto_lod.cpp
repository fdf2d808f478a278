#include "app/auto_lod.h"

#include <algorithm>

#include "rgb/lod/limit_error.h"
#include "rgb/lod/lod_criteria.h"
#include "rgb/lod/lod_driver.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/surface_error.h"

namespace app {

namespace {

// The thresholds are shares of the base mesh's size, so that they (and the result) do not depend on the
// current detail.
rgb::LodSettings driver_settings(const rgb::Mesh& mesh, const AutoLodSettings& s) {
    rgb::LodSettings out;
    const double diagonal = rgb::bounding_box_diagonal(mesh.base());
    if (mesh.base().detail()) {
        out.value = rgb::on_mesh(rgb::detail_error_value(mesh.shared_base()));
        out.threshold = s.max_distance_fraction * diagonal;
    } else {
        out.threshold = s.max_edge_fraction * diagonal;
    }
    out.max_triangles = s.triangle_budget;
    // The threshold is a floor under the budget, which usually stops the run first: its room reserved
    // and faulted in ahead, as for a script's `budget` (the job's engine time 0.57-0.71 of what it was
    // without, on the bunny and the torus: docs/benchmarks.md). No uniform start: it would be one long step, and undone,
    // it would replace the mesh under the display's and the history's observers.
    out.room_for_budget = true;
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
