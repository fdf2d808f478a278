#pragma once
// A cage's detail positions (rgb/mesh/detail_positions.h) as an optional section of the saved
// adaptive state (state_format.h), written only for a mesh with detail:
//
//   #rgb section detail N              N: the number of stored points; then
//   #rgb detail-level K                state format 5: every base face's level (one grid level)
//   #rgb detail-face-levels K K ...    state format 6, instead: each base face's level in base face
//                                      order, up to 32 a line, as many as base faces
//   #rgb detail-origin T M NAME        the dense surface's triangles T, the points M that took its
//                                      nearest point, and its name (the rest of the line)
//   #rgb d X Y Z [X Y Z ...]           the N positions, up to 8 a line, in the order of
//                                      rgb::DetailPositions::grid_points
//
// A detail of one level is written as format 5, byte for byte as before per-face levels existed,
// so that an older rgbsub still reads it; per-face levels make the file format 6, which an older
// rgbsub refuses naming the version. So a saved file resumes without the dense mesh it was made
// from: every sampled point is where it was sampled, bit for bit, and the v lines are checked
// against them on loading.
#include <cstddef>
#include <cstdint>
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
    std::vector<std::uint8_t> face_levels;  // one per base face
    rgb::DetailOrigin origin;
    std::vector<glm::dvec3> values;
    std::size_t section_line = 0;  // the section's first line, for reasons
};

// Whether the base mesh's detail needs state format 6 (levels that differ between faces).
bool needs_face_levels(const rgb::DetailPositions& detail);

// Appends the section; nothing for a base mesh without detail.
void append_detail_section(const rgb::BaseMesh& base, std::string& out, const std::function<void()>& flush_if_full);

// Whether a record of this kind belongs to the detail section of a file of this format version.
bool is_detail_record(std::string_view kind, unsigned version);

// The section's records, checked against its announced count and the number of base faces; throws
// ObjError(BadState) naming the offending line (`section_line` for the counts).
SavedDetail parse_detail_section(std::span<const ObjStateLine> records, std::size_t announced, std::size_t base_faces,
                                 const ObjStateLine& section_line, const std::string& file);

// The detail over the base mesh of these positions and triangles, or the reason it does not fit them
// (naming the section's line).
std::shared_ptr<const rgb::DetailPositions> detail_over(const SavedDetail& saved, std::span<const glm::dvec3> base_positions,
                                                        std::span<const rgb::Triangle> base_triangles, std::string& reason);

}  // namespace rgbio
