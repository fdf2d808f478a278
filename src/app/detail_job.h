#pragma once
// Detail by size or by accuracy over the whole mesh, from the editor's panel (docs/requests.md "Detail by
// size, accuracy and view"): the request `refine --max-edge` / `--tolerance` and the script's
// `max-edge` / `tolerance` lines make (io/script/detail_edit.h), the LOD driver run a slice per frame so the
// window keeps drawing and Esc can stop it. Finished, it is exactly the command line's result and
// says so as its script line; a tolerance also measures the largest error reached.
#include <chrono>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "app/mesh_job.h"
#include "io/script/detail_edit.h"

namespace rgb {
class Mesh;
}

namespace app {

// The editor's detail panel: a criterion with its amount for the whole mesh, and the pixel threshold
// of the view-dependent mode (view_lod_job.h).
struct DetailSettings {
    rgbio::DetailCriterion criterion = rgbio::DetailCriterion::Tolerance;
    rgbio::Amount amount{0.1, true};  // 0.1% of the bounding-box diagonal
    double view_pixels = 4.0;
};

class DetailJob : public MeshJob {
public:
    // Throws std::invalid_argument for an edit the core refuses.
    DetailJob(rgb::Mesh& mesh, const rgbio::DetailEdit& edit, std::size_t max_triangles);
    ~DetailJob() override;
    DetailJob(const DetailJob&) = delete;
    DetailJob& operator=(const DetailJob&) = delete;

    bool step(std::chrono::microseconds slice) override;
    // The driver's estimate (rgb::LodDriver::progress): it cannot count its splits ahead.
    float progress() const override;
    bool changed() const override;
    std::string label() const override;
    void cancel() override { cancelled_ = true; }
    // The edit's script line once it ran to its end within the triangle limit; a cut-short result
    // is no line's result.
    std::optional<std::string> script() const override;

    // Once done, for a tolerance: the displayed surface's largest error (rgb::displayed_surface_error).
    const std::optional<double>& reached_error() const { return reached_error_; }
    // The triangle limit stopped it (at a band of the driver's order).
    bool budget_bound() const;

private:
    struct State;
    std::unique_ptr<State> state_;
    bool cancelled_ = false;
    std::optional<double> reached_error_;
};

}  // namespace app
