#pragma once
// First stage of loading: bytes -> OBJ records (vertex positions, polygons with their source lines,
// counts of ignored elements, rgbsub state comments). Checks the encoding and each line on its own;
// whole-mesh checks are in mesh_validation.h.
//
// Only `v`, `f`, `l`, `p` and `#rgb` lines matter here; texture coordinates, normals, groups,
// materials and smoothing groups are skipped. Numbers are parsed with std::from_chars, which is
// correctly rounded, so a coordinate written with 17 significant digits (or shortest round-trip
// form) comes back bit for bit.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

namespace rgbio {

// Coordinates beyond this magnitude are rejected: squared distances of such points lose all
// precision in the subdivision arithmetic, and real models are never that large.
inline constexpr double kMaxCoordinate = 1e12;

struct ObjPolygon {
    std::vector<std::uint32_t> vertices;  // 0-based, already resolved (negative OBJ indices too)
    std::size_t line = 0;
};

struct ObjStateLine {
    std::string_view text;  // after "#rgb "
    std::size_t line = 0;
};

struct ObjRecords {
    std::vector<glm::dvec3> positions;
    std::vector<std::size_t> position_lines;
    std::vector<ObjPolygon> polygons;
    std::size_t line_elements = 0;   // `l` lines, ignored
    std::size_t point_elements = 0;  // `p` lines, ignored
    std::vector<ObjStateLine> state;  // views into the text passed to parse_obj
};

// Throws ObjError (Empty, Binary, Utf16, Syntax, FaceIndexZero, FaceIndexOutOfRange,
// NonFiniteCoordinate, AbsurdCoordinate). `file` is only used in messages.
ObjRecords parse_obj(std::string_view text, const std::string& file);

}  // namespace rgbio
