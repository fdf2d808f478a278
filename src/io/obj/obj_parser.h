#pragma once
// Folder io/obj (the OBJ parser, numbers, blocks, errors): includes the core only.
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
#include <iterator>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "io/obj/loaded_mesh.h"
#include "rgb/support/progress.h"

namespace rgbio {

// Coordinates beyond this magnitude are rejected: squared distances of such points lose all
// precision in the subdivision arithmetic, and real models are never that large.
inline constexpr double kMaxCoordinate = 1e12;

// One face as read: views into ObjPolygons' flat arrays, valid while the ObjRecords live.
struct ObjPolygon {
    std::span<const std::uint32_t> vertices;   // 0-based, already resolved (negative OBJ indices too)
    std::span<const std::uint32_t> texcoords;  // empty when no corner names a vt; else per corner, or kNoIndex
    std::size_t line = 0;
    std::uint32_t material = kNoIndex;  // indices into ObjRecords' name tables
    std::uint32_t group = kNoIndex;
    std::uint32_t object = kNoIndex;
    std::uint32_t smoothing_group = 0;  // 0: off
};

// The faces of a file in flat arrays: a few allocations for all of them rather than one per face
// (a saved 6M-triangle file has 6M faces). A label column stays empty while every face has the
// default label.
class ObjPolygons {
public:
    class iterator {
    public:
        using iterator_category = std::input_iterator_tag;
        using value_type = ObjPolygon;
        using difference_type = std::ptrdiff_t;
        using pointer = void;
        using reference = ObjPolygon;
        iterator(const ObjPolygons* polygons, std::size_t i) : polygons_(polygons), i_(i) {}
        ObjPolygon operator*() const { return (*polygons_)[i_]; }
        iterator& operator++() {
            ++i_;
            return *this;
        }
        bool operator==(const iterator& o) const { return i_ == o.i_; }

    private:
        const ObjPolygons* polygons_;
        std::size_t i_;
    };

    std::size_t size() const { return lines_.size(); }
    bool empty() const { return lines_.empty(); }
    ObjPolygon operator[](std::size_t i) const;
    // Every face's vertices one after the other (3 per face where all are triangles).
    std::span<const std::uint32_t> all_vertices() const { return vertices_; }
    // Whether some face has a texture coordinate, or a label other than the default in the given
    // field (material, group, object or smoothing_group), without looking at every face.
    bool has_texcoords() const { return !texcoords_.empty(); }
    bool has_labels(std::uint32_t ObjPolygon::*field) const;
    // Whether some face has any label (usemtl, g, o, or s other than off): most saved files have none,
    // and what labels need (a base face lookup per face, an index per face) is then skipped.
    bool has_any_labels() const { return !material_.empty() || !group_.empty() || !object_.empty() || !smoothing_group_.empty(); }
    iterator begin() const { return {this, 0}; }
    iterator end() const { return {this, size()}; }

    void reserve(std::size_t faces, std::size_t corners);
    // `texcoords` is empty or has one entry per vertex (kNoIndex where a corner names none).
    void add(std::span<const std::uint32_t> vertices, std::span<const std::uint32_t> texcoords, std::size_t line,
             std::uint32_t material, std::uint32_t group, std::uint32_t object, std::uint32_t smoothing_group);
    // Appends the faces of a later part of the file in two parts that may run at the same time (on two
    // threads: a large file's faces are about 100 MB): their corners (vertices, texture coordinates)
    // and their per-face arrays (where their corners start, lines, labels with ids mapped through the
    // tables: the new id of each of `other`'s ids). `corners_before`: all_vertices().size() before
    // either part.
    void append_corners(const ObjPolygons& other);
    void append_faces(const ObjPolygons& other, std::size_t corners_before, std::span<const std::uint32_t> material,
                      std::span<const std::uint32_t> group, std::span<const std::uint32_t> object);

private:
    std::vector<std::uint32_t> start_{0};  // polygon i's corners are [start_[i], start_[i + 1])
    std::vector<std::uint32_t> vertices_;
    std::vector<std::uint32_t> texcoords_;  // empty, or one per corner
    std::vector<std::uint32_t> lines_;      // the file is below 4 GiB, so are its line numbers
    std::vector<std::uint32_t> material_, group_, object_, smoothing_group_;  // empty: all default
};

struct ObjStateLine {
    std::string_view text;  // after "#rgb "
    std::size_t line = 0;
};

// Lines of one kind that were skipped: how many, and the first one.
struct SkippedLines {
    std::size_t count = 0;
    std::size_t first_line = 0;
    std::string first_keyword;  // a copy: the records outlive the text when a saved file is loaded
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
    ObjPolygons polygons;
    std::vector<std::string> material_names, group_names, object_names;  // in order of first use by a face
    std::vector<std::string> material_libraries;
    std::size_t line_elements = 0;   // `l` lines, ignored
    std::size_t point_elements = 0;  // `p` lines, ignored
    SkippedLines normals;            // vn lines, dropped
    SkippedLines unsupported;        // OBJ statements rgbsub does not use (free-form geometry, ...)
    SkippedLines unknown;            // keywords that are not OBJ
    std::vector<ObjStateLine> state;  // views into the text passed to parse_obj
    // Lines starting "v " and "f " exactly, and the number of the last line: what a truncation check
    // counts (truncation_check.h), gathered on the way so that it needs no second pass over the text.
    std::size_t v_line_starts = 0, f_line_starts = 0, last_line = 0;
    std::vector<ObjStateLine> tags;   // OpenSubdiv tag lines (t), after "t "; read by crease_tags.h
};

// Throws ObjError (Empty, Binary, Utf16, Syntax, FaceIndexZero, FaceIndexOutOfRange,
// NonFiniteCoordinate, AbsurdCoordinate). `file` is only used in messages; `progress` hears of the
// bytes parsed.
ObjRecords parse_obj(std::string_view text, const std::string& file, const rgb::ProgressSpan& progress = {});

}  // namespace rgbio
