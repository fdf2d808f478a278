#pragma once
// Budget-driven automatic level of detail (spec §3.3): the core's LodDriver splitting edges longer
// than a share of the base mesh's size, longest first, run a slice at a time so the window stays
// responsive and the job can be cancelled.
#include <cstddef>
#include <memory>

#include "app/mesh_job.h"

namespace rgb {
class Mesh;
}

namespace app {

struct AutoLodSettings {
    std::size_t triangle_budget = 100000;
    // Criterion: edges longer than this fraction of the mesh's bounding-box diagonal get refined.
    double max_edge_fraction = 0.01;
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
