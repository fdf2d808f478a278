#include "io/script/detail_edit.h"

#include <charconv>
#include <cmath>
#include <cstdint>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "io/obj/number_format.h"
#include "io/script/triangle_limit.h"
#include "rgb/lod/limit_error.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/surface_error.h"

namespace rgbio {

std::optional<Amount> parse_amount(const std::string& text) {
    Amount amount;
    std::string number = text;
    if (!number.empty() && number.back() == '%') {
        amount.percent = true;
        number.pop_back();
    }
    const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), amount.value);
    if (ec != std::errc() || end != number.data() + number.size() || !std::isfinite(amount.value) || !(amount.value > 0.0))
        return std::nullopt;
    return amount;
}

std::string format_amount(const Amount& amount) {
    std::string out;
    append_double(out, amount.value);
    out.erase(0, out.find_first_not_of(' '));
    if (amount.percent) out += '%';
    return out;
}

double world_amount(const rgb::Mesh& mesh, const Amount& amount) {
    if (!amount.percent) return amount.value;
    const rgb::BaseMesh& base = mesh.base();
    glm::dvec3 lo(1e300), hi(-1e300);
    for (std::uint32_t v = 0; v < base.num_vertices(); ++v) {
        lo = glm::min(lo, base.position(v));
        hi = glm::max(hi, base.position(v));
    }
    return amount.value / 100.0 * glm::distance(lo, hi);
}

MemoryUse memory_use(DetailCriterion criterion) {
    return criterion == DetailCriterion::Tolerance ? MemoryUse::Tolerance : MemoryUse::MaxEdge;
}

rgb::DetailRequest detail_request(const rgb::Mesh& mesh, const DetailEdit& edit, std::size_t max_triangles) {
    rgb::DetailRequest request;
    request.kind = edit.kind;
    request.threshold = world_amount(mesh, edit.amount);
    request.value = edit.criterion == DetailCriterion::MaxEdge ? rgb::edge_length_value(mesh.shared_base())
                                                               : rgb::limit_error_value(mesh.shared_base(), request.threshold);
    if (edit.criterion == DetailCriterion::Tolerance) request.shrink_per_level = 4.0;
    if (edit.criterion == DetailCriterion::MaxEdge) request.mesh_value = rgb::edge_length;
    request.sphere = edit.sphere;
    request.max_triangles = max_triangles;
    return request;
}

DetailOutcome apply_detail_edit(rgb::Mesh& mesh, const DetailEdit& edit, std::size_t max_triangles) {
    DetailOutcome outcome;
    const rgb::DetailRequest request = detail_request(mesh, edit, max_triangles);
    check_detail_size(mesh, request, max_triangles);
    outcome.report = rgb::apply_detail_request(mesh, request);
    if (outcome.report.budget_bound)
        throw TooLarge("the request needs more than " + std::to_string(max_triangles) +
                       " triangles (set by this machine's memory; --max-triangles changes it)");
    if (edit.criterion == DetailCriterion::Tolerance && !edit.sphere && edit.kind == rgb::RequestKind::Set)
        outcome.reached_error = rgb::displayed_surface_error(mesh).max_error;
    return outcome;
}

}  // namespace rgbio
