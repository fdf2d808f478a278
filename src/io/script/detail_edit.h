#pragma once
// Detail asked for by size or by accuracy (docs/requests.md "Detail by size, accuracy and view"), as the
// command line (`refine --max-edge`, `--tolerance`), scripts (`max-edge`, `tolerance` lines) and the
// editor put it: an amount in world units or as a percentage of the input's bounding-box diagonal,
// over the whole surface or in a ball of base space; carried out by rgb::apply_detail_request.
#include <cstddef>
#include <optional>
#include <string>

#include "io/script/triangle_limit.h"
#include "rgb/lod/lod_criteria.h"
#include "rgb/lod/requests.h"

namespace rgbio {

enum class DetailCriterion {
    MaxEdge,    // no green edge longer than the amount in the uniform mesh of its level
    Tolerance,  // the displayed surface within the amount of the limit surface
};

// A length as written: world units, or with a trailing '%' a share of the bounding-box diagonal.
struct Amount {
    double value = 0.0;
    bool percent = false;
};
// A positive finite number, optionally followed by '%'; nullopt otherwise.
std::optional<Amount> parse_amount(const std::string& text);
std::string format_amount(const Amount& amount);

struct DetailEdit {
    DetailCriterion criterion = DetailCriterion::MaxEdge;
    Amount amount;
    rgb::RequestKind kind = rgb::RequestKind::Set;
    std::optional<rgb::Sphere> sphere;
};

// The edit's amount in world units: a percentage of the diagonal of the base mesh's bounding box.
double world_amount(const rgb::Mesh& mesh, const Amount& amount);

// The path whose memory a criterion's edit costs (triangle_limit.h).
MemoryUse memory_use(DetailCriterion criterion);

// The core's request for the edit on this mesh.
rgb::DetailRequest detail_request(const rgb::Mesh& mesh, const DetailEdit& edit, std::size_t max_triangles);

struct DetailOutcome {
    rgb::LodReport report;
    // For a tolerance over the whole surface: the displayed surface's largest error at the samples
    // of rgb::displayed_surface_error (within the tolerance unless the level cap bound).
    std::optional<double> reached_error;
};

// Throws TooLarge (triangle_limit.h) when the request needs more than max_triangles triangles; the
// mesh is then cut short (at a band of the driver's order over the whole surface).
DetailOutcome apply_detail_edit(rgb::Mesh& mesh, const DetailEdit& edit, std::size_t max_triangles);

}  // namespace rgbio
