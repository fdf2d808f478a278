#pragma once
// The base vertices' colours (`v x y z r g b`) as an optional section of the saved adaptive state
// (state_format.h), written only for a mesh with vertex colours:
//
//   #rgb section base-colours N        N: the number of base vertices; then lines
//   #rgb colour R G B [R G B ...]      the base vertices' colours in base order, up to 8 a line
//
// Every vertex colour of the adaptive mesh follows from them exactly (rgb/values/vertex_channel.h), so a
// refined file resumes with its colours: the v lines' colours are checked against them on loading
// like the positions, and an edit in another program wins over the state.
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "io/obj/obj_parser.h"

namespace rgbio {

inline constexpr std::string_view kColourRecord = "colour";

// Appends the section; nothing when `colours` is empty.
void append_colour_section(std::span<const glm::dvec3> colours, std::string& out, const std::function<void()>& flush_if_full);

// The section's `colour` records, checked against its announced count and the number of base
// vertices; throws ObjError(BadState) naming the offending line (`section_line` for the counts).
std::vector<glm::dvec3> parse_colour_section(std::span<const ObjStateLine> records, std::size_t announced, std::size_t base_vertices,
                                             const ObjStateLine& section_line, const std::string& file);

// Why the body's vertex colours (records.colours, one per v line) differ from `colours` (one per
// vertex of the restored mesh, as its base-colours section gives them: rgb::RestoredChannel), or
// nothing when all agree bit for bit.
std::optional<std::string> colour_mismatch(std::span<const glm::dvec3> colours, const ObjRecords& records);

}  // namespace rgbio
