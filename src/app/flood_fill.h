#pragma once
// "Set all to level N": every face refined or coarsened to level N, as a MeshJob that feeds the
// engine a batch of base faces per step.
#include <cstdint>

#include "app/mesh_job.h"

namespace rgb {
class Mesh;
}

namespace app {

class FloodFillJob : public MeshJob {
public:
    FloodFillJob(rgb::Mesh& mesh, int level);
    bool step(std::chrono::microseconds slice) override;
    float progress() const override;
    bool changed() const override { return changed_; }
    std::string label() const override;

private:
    rgb::Mesh& mesh_;
    int level_;
    std::uint32_t next_base_face_ = 0;
    bool changed_ = false;
};

}  // namespace app
