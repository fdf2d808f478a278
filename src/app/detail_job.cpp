#include "app/detail_job.h"

#include "rgb/lod/lod_criteria.h"
#include "rgb/lod/lod_driver.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/surface_error.h"

namespace app {

struct DetailJob::State {
    State(rgb::Mesh& m, const rgbio::DetailEdit& e, std::size_t max_triangles)
        : mesh(m), edit(e), driver(m, rgb::whole_surface_settings(rgbio::detail_request(m, e, max_triangles))) {}
    rgb::Mesh& mesh;
    rgbio::DetailEdit edit;
    rgb::LodDriver driver;
};

DetailJob::DetailJob(rgb::Mesh& mesh, const rgbio::DetailEdit& edit, std::size_t max_triangles)
    : state_(std::make_unique<State>(mesh, edit, max_triangles)) {}

DetailJob::~DetailJob() = default;

bool DetailJob::step(std::chrono::microseconds slice) {
    State& s = *state_;
    if (cancelled_) return false;
    const auto deadline = std::chrono::steady_clock::now() + slice;
    do s.driver.run(64);
    while (!s.driver.done() && std::chrono::steady_clock::now() < deadline);
    if (!s.driver.done()) return true;
    if (s.edit.criterion == rgbio::DetailCriterion::Tolerance) reached_error_ = rgb::displayed_surface_error(s.mesh).max_error;
    return false;
}

float DetailJob::progress() const { return static_cast<float>(state_->driver.progress()); }

bool DetailJob::changed() const {
    const rgb::LodReport& r = state_->driver.report();
    return r.splits + r.removals > 0;
}

std::string DetailJob::label() const {
    const bool size = state_->edit.criterion == rgbio::DetailCriterion::MaxEdge;
    return std::string(size ? "max edge " : "tolerance ") + rgbio::format_amount(state_->edit.amount);
}

std::optional<std::string> DetailJob::script() const {
    if (cancelled_ || !state_->driver.done() || budget_bound()) return std::nullopt;
    const bool size = state_->edit.criterion == rgbio::DetailCriterion::MaxEdge;
    return std::string(size ? "max-edge " : "tolerance ") + rgbio::format_amount(state_->edit.amount) + "\n";
}

bool DetailJob::budget_bound() const { return state_->driver.report().budget_bound; }

}  // namespace app
