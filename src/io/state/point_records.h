#pragma once
// Records of points in the saved state (state_format.h): "#rgb NAME X Y Z [X Y Z ...]", up to 8 points
// a line, each number in shortest round-trip form, as the base-colours and detail sections hold them.
#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "io/state/state_line_reader.h"

namespace rgbio {

// Appends the records (formatted on all cores, the same bytes as in one loop), calling
// flush_if_full() after every few hundred lines.
void append_point_records(std::string& out, std::string_view name, std::span<const glm::dvec3> points,
                          const std::function<void()>& flush_if_full);

// Appends the points of one record (after its name) to `points`; fails naming the line when it would
// hold more than `announced` in all (so that a forged file cannot make the list grow without end),
// calling them `what`.
void read_point_record(StateLineReader& r, std::vector<glm::dvec3>& points, std::size_t announced, const std::string& what);

}  // namespace rgbio
