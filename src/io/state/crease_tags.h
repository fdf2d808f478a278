#pragma once
// Crease and corner tags (rgb/rules/sharp_features.h) in files, two ways:
//
// * OpenSubdiv's OBJ tag lines (its shape_utils format: `t NAME INTS/FLOATS/STRINGS values...`),
//   which shapes from its ecosystem carry and other programs read:
//     t crease 2/1/0 A B SHARPNESS          (pairs of 0-based vertex indices; one sharpness for all
//                                            pairs, or one per pair)
//     t corner 1/1/0 V SHARPNESS            (vertices; one sharpness, or one per vertex)
//     t interpolateboundary 1/0/0 K         (1 edge-and-corner, 2 edge-only; 0, "none", is refused)
//   Other tag names (hole, creasingmethod, face-varying options...) are skipped with a warning.
//   rgbsub supports integer sharpness 0-10 (10 and above: infinitely sharp); a fractional value is
//   refused, naming the line, rather than silently changed.
// * Records of the saved adaptive state (state_format.h, version 4), which hold the base mesh's tags
//   exactly:
//     #rgb boundary edge-and-corner|edge-only
//     #rgb crease A B S [A B S ...]         (base vertices, up to 8 edges a line)
//     #rgb corner V S [V S ...]
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "io/obj/loaded_mesh.h"
#include "io/obj/obj_parser.h"
#include "rgb/mesh/mesh.h"
#include "rgb/rules/sharp_features.h"

namespace rgbio {

// The tags of a file's t lines in its own vertex numbering (0-based v lines), each with its line.
struct FileTags {
    rgb::SharpFeatures features;
    std::vector<std::size_t> edge_lines, corner_lines;  // parallel to features.edges / corners
    SkippedLines ignored;                               // tags of other names
};

// Throws ObjError(BadTag) naming the line: a malformed line, an index beyond the file's vertices, a
// negative, fractional or non-finite sharpness, boundary interpolation "none".
FileTags parse_tag_lines(std::span<const ObjStateLine> lines, std::size_t file_vertices, const std::string& file);

// Sets mesh.sharp_features from the file's tags in the mesh's numbering (mesh.file_vertex): a tag on
// a vertex a repair split into copies applies to every copy. Throws ObjError(BadTag) for a crease
// that joins no edge of the mesh or a corner on a vertex used by no face. Adds a warning for skipped
// tags.
void attach_file_tags(const FileTags& tags, LoadedMesh& mesh, const std::string& file);

// The t lines describing the written mesh `mesh` (obj_index: its vertex slots' 0-based indices in
// the file): every edge along a tagged base edge with the sharpness it has at its level (uniform
// creasing: s - level, 10 stays 10), every tagged base vertex with its corner sharpness at its
// display level, and the boundary option if it is edge-and-corner. For a uniform mesh of level k,
// OpenSubdiv refining the file gives the surface rgbsub does.
void append_tag_lines(const rgb::Mesh& mesh, std::span<const std::uint32_t> obj_index, std::string& out);

// The base mesh's tags as state records; nothing for a base mesh without tags.
void append_state_tag_records(const rgb::SharpFeatures& features, std::string& out);
// Whether a state record kind is one of the above ("boundary", "crease", "corner").
bool is_state_tag_record(std::string_view kind);
// The tags of those records (each line's text after "#rgb "). Throws ObjError(BadState) naming the line.
rgb::SharpFeatures parse_state_tag_records(std::span<const ObjStateLine> lines, const std::string& file);

}  // namespace rgbio
