#pragma once
// The adaptive state of a saved mesh as OBJ comment lines starting with "#rgb", which other OBJ
// readers skip. The OBJ body (v and f lines) is the adaptive mesh itself; the state adds only what
// the body cannot say: the base mesh it refines and each vertex's address in the hierarchy
// (rgb::MeshState). Everything else (face colours, Loop positions) follows from those exactly.
// Doubles are written in shortest round-trip form and read with std::from_chars: bit for bit.
//
//   #rgb state 2                       format version
//   #rgb positions displayed|limit     which positions the v lines hold (checked on loading)
//   #rgb section base-vertices N       then N lines   #rgb p X Y Z
//   #rgb section base-faces N          then lines     #rgb t A B C [A B C ...]   (0-based)
//   #rgb section addresses N           then lines     #rgb a FACE A1 A2 LEVEL [...]
//                                      one address per non-base vertex, in v-line order after the
//                                      base vertices (which come first, in base order)
//   #rgb section face-labels N         optional: the base faces' usemtl/g/o/s labels (face_label_state.h)
//   #rgb end
// A later version adds sections; a reader refuses a section it does not know, naming it. Optional
// sections (face-labels) are written only when there is something to say, so a mesh without them
// stays readable by an rgbsub that does not know them.
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "io/obj_parser.h"
#include "rgb/state.h"

namespace rgbio {

inline constexpr unsigned kStateFormatVersion = 2;

struct SavedState {
    rgb::MeshState mesh;           // faces are not part of the state: the reader takes the f lines
    bool limit_positions = false;  // the v lines hold limit positions, not displayed ones
    BaseFaceLabels labels;         // empty without a face-labels section
};

// Appends the state's lines to `out`, calling flush_if_full() between lines so that a file writer can
// empty the buffer (the state of a large mesh is tens of megabytes).
// `labels` (per base face) become the optional face-labels section.
void write_state(const rgb::MeshState& state, bool limit_positions, std::string& out, const std::function<void()>& flush_if_full,
                 const BaseFaceLabels& labels = {});

// The #rgb lines of a file, or nothing when they are not an rgbsub state at all (no `#rgb state`
// header first: some other program's comments). Throws ObjError(BadState) naming the offending line,
// and for another format version, naming it.
std::optional<SavedState> parse_state(std::span<const ObjStateLine> lines, const std::string& file);

}  // namespace rgbio
