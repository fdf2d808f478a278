#pragma once
// A cage's detail positions (rgb/mesh/detail_positions.h) as an optional section of the saved
// adaptive state (state_format.h), written only for a mesh with detail, in state format version 5:
//
//   #rgb section detail N              N: the number of points of the detail grid; then
//   #rgb detail-level K                the grid's level (its points are those of Σ_K)
//   #rgb detail-origin T M NAME        the dense surface's triangles T, the points M that took its
//                                      nearest point, and its name (the rest of the line)
//   #rgb d X Y Z [X Y Z ...]           the N positions, up to 8 a line, in the order of
//                                      rgb::DetailPositions::grid_points
//
// So a saved file resumes without the dense mesh it was made from: every vertex of every level up to
// K is at its sampled point, bit for bit, and the v lines are checked against them on loading.
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "io/obj/obj_parser.h"
#include "rgb/mesh/base_mesh.h"
#include "rgb/mesh/detail_positions.h"

namespace rgbio {

inline constexpr std::string_view kDetailRecord = "d";

// The section's records as read, before a base mesh exists to give them their places.
struct SavedDetail {
    int level = 0;
    rgb::DetailOrigin origin;
    std::vector<glm::dvec3> values;
};

// Appends the section; nothing for a base mesh without detail.
void append_detail_section(const rgb::BaseMesh& base, std::string& out, const std::function<void()>& flush_if_full);

// Whether a record of this kind belongs to the detail section.
bool is_detail_record(std::string_view kind);

// The section's records, checked against its announced count; throws ObjError(BadState) naming the
// offending line (`section_line` for the counts).
SavedDetail parse_detail_section(std::span<const ObjStateLine> records, std::size_t announced, const ObjStateLine& section_line,
                                 const std::string& file);

// The detail over the base mesh of these positions and triangles, or the reason it does not fit them.
std::shared_ptr<const rgb::DetailPositions> detail_over(const SavedDetail& saved, std::span<const glm::dvec3> base_positions,
                                                        std::span<const rgb::Triangle> base_triangles, std::string& reason);

}  // namespace rgbio
