#pragma once
// The adaptive RGB state (rgb::MeshState, slot for slot) as OBJ comment lines starting with "#rgb",
// which other OBJ readers skip as comments. Doubles are written in shortest round-trip form
// (std::to_chars) and read with std::from_chars, so every value comes back bit for bit.
//
//   #rgb state 1 VERTEX_SLOTS FACE_SLOTS BASE_VERTICES
//   #rgb v ALIVE LEVEL BOUNDARY X Y Z [LX LY LZ]        one per vertex slot (insertion position p^l,
//                                                       then the limit p^inf when known)
//   #rgb f ALIVE A B C COLOUR LEVEL RED_EDGE            one per face slot (COLOUR 0 green, 1 red, 2 blue)
//   #rgb valence N...                                   base valences, in order, several per line
//   #rgb free_vertices N... / #rgb free_faces N...      free lists, in order (may be absent)
//   #rgb end
#include <span>
#include <string>

#include "io/obj_parser.h"
#include "rgb/state.h"

namespace rgbio {

std::string format_state(const rgb::MeshState& state);

// Throws ObjError(BadState) naming the offending line.
rgb::MeshState parse_state(std::span<const ObjStateLine> lines, const std::string& file);

}  // namespace rgbio
