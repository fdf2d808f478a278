#include "rgb/rules/sharp_features.h"

namespace rgb {

const char* boundary_interpolation_name(BoundaryInterpolation b) {
    return b == BoundaryInterpolation::EdgeOnly ? "edge-only" : "edge-and-corner";
}

std::optional<BoundaryInterpolation> parse_boundary_interpolation(std::string_view name) {
    if (name == "edge-only") return BoundaryInterpolation::EdgeOnly;
    if (name == "edge-and-corner") return BoundaryInterpolation::EdgeAndCorner;
    return std::nullopt;
}

}  // namespace rgb
