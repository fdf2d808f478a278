#pragma once
// Budget-driven automatic level of detail (spec §3.3): the core's LodDriver run a slice at a time so
// the window stays responsive and the job can be cancelled. On a plain mesh it splits edges longer
// than a share of the base mesh's size, longest first; on a cage with detail it splits where the
// surface departs from the dense mesh by more than a share of that size, farthest first, as a
// script's `budget` line orders them (docs/detail.md), so the budget goes where it gains most.
#include <cstddef>
#include <memory>

#include "app/mesh_job.h"

namespace rgb {
class Mesh;
}

namespace app {

struct AutoLodSettings {
    std::size_t triangle_budget = 100000;
    // Sizes as fractions of the base mesh's bounding-box diagonal (rgb::bounding_box_diagonal).
    // On a plain mesh: edges longer than this get refined.
    double max_edge_fraction = 0.01;
    // On a cage with detail: edges next to which the surface departs from the dense mesh by more than
    // this get refined (rgb::detail_error_value). 0.01% is a tenth of a pixel with the mesh 1000
    // pixels across, so the budget rather than the threshold usually stops the run; it keeps a budget
    // from going to flat parts where the departure is noise.
    double max_distance_fraction = 1e-4;
};

class AutoLodJob : public MeshJob {
public:
    AutoLodJob(rgb::Mesh& mesh, const AutoLodSettings& settings);
    ~AutoLodJob() override;
    AutoLodJob(const AutoLodJob&) = delete;
    AutoLodJob& operator=(const AutoLodJob&) = delete;

    bool step(std::chrono::microseconds slice) override;
    // The share of the triangle budget reached so far (1 once the criterion is met).
    float progress() const override;
    bool changed() const override;
    std::string label() const override { return "automatic LOD"; }
    void cancel() override { cancelled_ = true; }
    // The editor's criterion is not the script's `budget`.
    std::optional<std::string> script() const override { return std::nullopt; }

private:
    struct State;
    std::unique_ptr<State> state_;
    bool cancelled_ = false;
};

}  // namespace app
