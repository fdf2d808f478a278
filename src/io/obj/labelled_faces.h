#pragma once
// The order in which a saved OBJ lists the faces of an adaptive mesh, and the usemtl/g/o/s lines
// between them. Each face takes the labels of the base face it lies in (rgb::base_face_of); faces
// are grouped by those labels, the groups in the order their labels first appear on the base faces
// (the input's order), faces within a group in slot order. So a file has one label block per
// distinct label combination however finely it is refined, and a mesh without labels keeps slot
// order with no label lines at all.
#include <cstddef>
#include <string>
#include <vector>

#include "io/obj/loaded_mesh.h"
#include "rgb/mesh/mesh.h"

namespace rgbio {

struct LabelledFaceOrder {
    std::vector<rgb::FaceId> faces;  // every live face once
    struct Block {
        std::size_t first = 0;  // index into faces of the block's first face
        std::string lines;      // written before it: the labels that change there ("o", "g", "usemtl", "s")
    };
    std::vector<Block> blocks;  // by first; empty without labels
};

LabelledFaceOrder labelled_face_order(const rgb::Mesh& mesh, const BaseFaceLabels& labels);

}  // namespace rgbio
