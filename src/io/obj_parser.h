#pragma once
// First stage of loading: bytes -> OBJ records (positions with optional colours, texture
// coordinates, polygons with their corners' texture coordinates, labels and source lines, counts of
// ignored elements, rgbsub state comments). Checks the encoding and each line on its own;
// whole-mesh checks are in mesh_validation.h.
//
// Read: v (x y z [w] or x y z r g b), vt (u [v [w]]), f (v, v/vt, v//vn, v/vt/vn corners), usemtl,
// g, o, s, mtllib, #rgb, t (OpenSubdiv tags, collected for crease_tags.h). Counted and reported: vn (dropped: normals of the input surface do not
// belong to the subdivided one), l, p, free-form statements and unknown keywords. Lines end at LF,
// CRLF or a lone CR. Numbers are parsed with std::from_chars, which is correctly rounded, so a
// coordinate written with 17 significant digits (or shortest round-trip form) comes back bit for bit.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "io/loaded_mesh.h"

namespace rgbio {

// Coordinates beyond this magnitude are rejected: squared distances of such points lose all
// precision in the subdivision arithmetic, and real models are never that large.
inline constexpr double kMaxCoordinate = 1e12;

struct ObjPolygon {
    std::vector<std::uint32_t> vertices;   // 0-based, already resolved (negative OBJ indices too)
    std::vector<std::uint32_t> texcoords;  // empty when no corner names a vt; else per corner, or kNoIndex
    std::size_t line = 0;
    std::uint32_t material = kNoIndex;  // indices into ObjRecords' name tables
    std::uint32_t group = kNoIndex;
    std::uint32_t object = kNoIndex;
    std::uint32_t smoothing_group = 0;  // 0: off
};

struct ObjStateLine {
    std::string_view text;  // after "#rgb "
    std::size_t line = 0;
};

// Lines of one kind that were skipped: how many, and the first one.
struct SkippedLines {
    std::size_t count = 0;
    std::size_t first_line = 0;
    std::string_view first_keyword;  // a view into the parsed text
    void add(std::size_t line, std::string_view keyword);
};

struct ObjRecords {
    std::vector<glm::dvec3> positions;
    std::vector<std::size_t> position_lines;
    // Empty when no v line has a colour; otherwise one per position, with has_colour[i] == 0 where
    // the v line gave none (colour then 0).
    std::vector<glm::dvec3> colours;
    std::vector<std::uint8_t> has_colour;
    std::vector<glm::dvec2> texcoords;
    SkippedLines texcoord_w;  // vt lines with a non-zero w, which is dropped
    std::vector<ObjPolygon> polygons;
    std::vector<std::string> material_names, group_names, object_names;  // in order of first use by a face
    std::vector<std::string> material_libraries;
    std::size_t line_elements = 0;   // `l` lines, ignored
    std::size_t point_elements = 0;  // `p` lines, ignored
    SkippedLines normals;            // vn lines, dropped
    SkippedLines unsupported;        // OBJ statements rgbsub does not use (free-form geometry, ...)
    SkippedLines unknown;            // keywords that are not OBJ
    std::vector<ObjStateLine> state;  // views into the text passed to parse_obj
    std::vector<ObjStateLine> tags;   // OpenSubdiv tag lines (t), after "t "; read by crease_tags.h
};

// Throws ObjError (Empty, Binary, Utf16, Syntax, FaceIndexZero, FaceIndexOutOfRange,
// NonFiniteCoordinate, AbsurdCoordinate). `file` is only used in messages.
ObjRecords parse_obj(std::string_view text, const std::string& file);

}  // namespace rgbio
