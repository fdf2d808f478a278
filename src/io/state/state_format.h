#pragma once
// Folder io/state (the versioned state format and its sections): includes io/obj and the core.
// The adaptive state of a saved mesh as OBJ comment lines starting with "#rgb", which other OBJ
// readers skip. The OBJ body (v and f lines) is the adaptive mesh itself; the state adds only what
// the body cannot say: the base mesh it refines and each vertex's address in the hierarchy
// (rgb::MeshState). Everything else (face colours, Loop positions) follows from those exactly.
// Doubles are written in shortest round-trip form and read with std::from_chars: bit for bit.
//
//   #rgb state 3                       format version (version 2, without the -as- records, is read too)
//   #rgb positions displayed|limit     which positions the v lines hold (checked on loading)
//   #rgb section base-vertices N       then, for the base vertices in order, lines
//                                        #rgb p X Y Z        a base vertex's position
//                                        #rgb p-as-v COUNT   the next COUNT base vertices are where their
//                                                            own v lines put them (base vertex i is the
//                                                            i-th v line: the base vertices come first)
//   #rgb section base-faces N          then, for the base faces in order, lines
//                                        #rgb t A B C [A B C ...]   explicit (0-based base vertices)
//                                        #rgb t-as-f FIRST COUNT    the next COUNT base faces are the faces of
//                                                                   the f lines FIRST, FIRST+1, ... (0-based
//                                                                   among the f lines), corner for corner
//   #rgb section addresses N           then lines     #rgb a FACE A1 A2 LEVEL [...]
//                                      one address per non-base vertex, in v-line order after the
//                                      base vertices (which come first, in base order)
//   #rgb section base-uvs N            optional, for a mesh with texture coordinates: the base mesh's
//                                      UV channel (rgb/values/uv_layout.h), from which every UV of the adaptive
//                                      mesh follows exactly (rgb/values/uv_evaluator.h); records
//                                        #rgb uv-interpolation none|corners|boundaries|all
//                                        #rgb uv U V [U V ...]       the N values in order
//                                        #rgb uv-faces A B C [...]   per base face in order, its corners' values
//                                        #rgb uv-untextured F [...]  base faces the input gave no UVs (sorted)
//   #rgb section base-colours N        optional: the base vertices' colours (base_colour_state.h)
//   #rgb section face-labels N         optional: the base faces' usemtl/g/o/s labels (face_label_state.h)
//   #rgb section detail N              version 5: a cage's detail positions (detail_state.h);
//                                      version 6: the same with a detail level per base face
//   #rgb end
// The -as- records keep a lightly refined file from repeating its base mesh (a base vertex shown at
// level 0 and an untouched base face are in the body already): the state stays a small fraction of
// the v and f lines. Whatever they take from the body is checked with the rest (the restored mesh
// must give back every v and f line), so an edited body cannot pass as the saved mesh.
// Version 4 is version 3 plus the base mesh's crease and corner tags (crease_tags.h), records before
// '#rgb end'; it is written only for a base mesh with tags, so untagged files stay version 3 and
// readable by older rgbsub, which refuse a version-4 file naming its version.
// A later version adds sections; a reader refuses a section it does not know, naming it. Optional
// sections (face-labels, base-uvs, base-colours) are written only when there is something to say, so
// a mesh without them stays readable by an rgbsub that does not know them.
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "io/obj/obj_parser.h"
#include "io/state/detail_state.h"
#include "rgb/mesh/state.h"
#include "rgb/values/uv_layout.h"

namespace rgbio {

inline constexpr unsigned kStateFormatVersion = 3;
// Written instead for a base mesh with crease or corner tags.
inline constexpr unsigned kTaggedStateFormatVersion = 4;
// Written instead for a cage with detail (detail_state.h): version 4 plus the detail section.
inline constexpr unsigned kDetailStateFormatVersion = 5;
// Written instead for a cage whose detail has levels that differ between base faces: version 5
// plus the detail-face-levels records.
inline constexpr unsigned kFaceLevelDetailStateFormatVersion = 6;
// The newest version read.
inline constexpr unsigned kNewestStateFormatVersion = kFaceLevelDetailStateFormatVersion;
// The oldest version still read.
inline constexpr unsigned kOldestStateFormatVersion = 2;

struct SavedState {
    rgb::MeshState mesh;           // faces are not part of the state: the reader takes the f lines
    bool limit_positions = false;  // the v lines hold limit positions, not displayed ones
    // Runs of base vertices and base faces that the body gives (p-as-v, t-as-f): their entries in
    // mesh.base_positions and mesh.base_triangles, and the base vertices' addresses in mesh.vertices,
    // are filled in by take_from_body.
    struct Run {
        std::size_t first_base = 0, count = 0;
        std::size_t first_face = 0;  // t-as-f: the first f line's index among the f lines
    };
    std::vector<Run> vertices_as_v, faces_as_f;
    std::optional<rgb::UvChannel> uvs;  // the base-uvs section, if any
    std::vector<glm::dvec3> colours;    // the base-colours section: empty, or one per base vertex
    BaseFaceLabels labels;  // empty without a face-labels section
    std::optional<SavedDetail> detail;  // the detail section, if any (its base mesh is not built yet)
};

// Appends the lines of the mesh's state (rgb::capture_state's, read from the mesh as they are
// written) to `out`, calling flush_if_full() between lines so that a file writer can empty the buffer
// (the state of a large mesh is tens of megabytes). `face_lines`: the live faces in the order of the
// file's f lines (which t-as-f records refer to), or empty for slot order. `display_levels`: with
// displayed positions, rgb::display_levels(mesh) (which the writer of the v lines has already), so
// that the base vertices' positions cost no walk around each. `labels` (per base face)
// become the optional face-labels section. `uvs`: the base mesh's UV channel, if any. `base_colours`:
// empty, or one colour per base vertex (the base-colours section).
void write_state(const rgb::Mesh& mesh, bool limit_positions, std::span<const std::uint8_t> display_levels, std::string& out,
                 const std::function<void()>& flush_if_full, std::span<const rgb::FaceId> face_lines = {}, const BaseFaceLabels& labels = {},
                 const rgb::UvChannel* uvs = nullptr, std::span<const glm::dvec3> base_colours = {});

// Removes from a file's #rgb lines those of another program: all of them when none is an rgbsub
// state's '#rgb state' line, else those before it and after its '#rgb end'. Returns the warning that
// says so, or nothing when every line belongs to the state.
std::optional<std::string> drop_foreign_state_lines(std::vector<ObjStateLine>& lines);

// The #rgb lines of a file, or nothing when they are not an rgbsub state at all (no `#rgb state`
// header first: some other program's comments). Throws ObjError(BadState) naming the offending line,
// and for another format version, naming it. The body's counts of v and f lines bound what a line
// may refer to, so that a forged count cannot exhaust memory.
std::optional<SavedState> parse_state(std::span<const ObjStateLine> lines, const std::string& file, std::size_t body_vertices,
                                      std::size_t body_faces);

// Completes the state with what it takes from the body (the v lines' positions, the f lines'
// faces) and the base vertices' addresses (each one's corner of a base face using it); the reason
// when the body does not have what the state refers to.
std::optional<std::string> take_from_body(SavedState& saved, std::span<const glm::dvec3> positions, const ObjPolygons& polygons);

}  // namespace rgbio
