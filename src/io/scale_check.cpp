#include "io/scale_check.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "io/obj/obj_error.h"

namespace rgbio {

std::optional<std::string> scale_problem(std::span<const glm::dvec3> positions, const ScaleRange& range) {
    if (positions.empty()) return std::nullopt;
    glm::dvec3 lo(HUGE_VAL), hi(-HUGE_VAL);
    for (const glm::dvec3& p : positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const double largest = std::max({-lo.x, -lo.y, -lo.z, hi.x, hi.y, hi.z});
    // Scaled before squaring: the extent itself may be beyond what a squared length holds.
    const glm::dvec3 half = 0.5 * (hi - lo);
    const double unit = std::max({half.x, half.y, half.z});
    const double across = unit > 0.0 ? 2.0 * unit * glm::length(half / unit) : 0.0;
    std::ostringstream reason;
    reason.precision(3);
    if (largest > range.largest_coordinate)
        reason << "a coordinate is " << largest << ", beyond the " << range.largest_coordinate << " that " << range.numbers << " allow";
    else if (across < range.smallest_extent && across > 0.0)
        reason << "the mesh is " << across << " across, less than the " << range.smallest_extent << " that " << range.numbers << " allow";
    else
        return std::nullopt;
    return reason.str() + "; scale it first";
}

void check_scale(std::span<const glm::dvec3> positions, std::initializer_list<ScaleRange> ranges, const std::string& file,
                 const char* action) {
    for (const ScaleRange& range : ranges)
        if (const std::optional<std::string> problem = scale_problem(positions, range))
            throw ObjError(ObjProblem::OutOfScale, file, 0, std::string("cannot ") + action + " this mesh: " + *problem);
}

}  // namespace rgbio
