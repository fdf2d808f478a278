#pragma once
// Sizes a mesh's numbers must keep (issue 30 item 14): a mesh a billionth of a billionth... across is
// valid OBJ, but its squared distances underflow doubles (every edge "0 long") and its positions
// turn into zeros as 32-bit floats (a blank render, a glTF of zeros). Such a mesh is refused with
// the reason rather than worked on silently wrong. The subdivided surface lies in the hull of the
// base mesh, so the base mesh's positions answer for every level.
#include <initializer_list>
#include <optional>
#include <span>
#include <string>

#include <glm/vec3.hpp>

namespace rgbio {

struct ScaleRange {
    double smallest_extent;    // a mesh less than this across (and not a point) cannot be used
    double largest_coordinate;  // nor one with a coordinate beyond this
    const char* numbers;       // what holds them, for the reason
};
// The core: squared lengths stay normal doubles.
inline constexpr ScaleRange kDoubleScale{1e-150, 1e150, "doubles, in which rgbsub squares lengths"};
// glTF and the renderer's buffers: positions as floats with most of their 24 bits.
inline constexpr ScaleRange kFloatScale{1e-30, 1e38, "32-bit floats"};

// Why the positions do not fit the range, ending in what to do; nothing when they fit.
std::optional<std::string> scale_problem(std::span<const glm::dvec3> positions, const ScaleRange& range);

// Throws ObjError(OutOfScale) for `file`, "cannot ACTION this mesh: " and the first range's problem,
// when the positions do not fit every range given.
void check_scale(std::span<const glm::dvec3> positions, std::initializer_list<ScaleRange> ranges, const std::string& file,
                 const char* action);

}  // namespace rgbio
