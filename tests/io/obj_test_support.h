#pragma once
// Helpers shared by the io tests: reading OBJ text in memory and asserting on the error it gives.
#include <algorithm>
#include <array>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "io/obj/loaded_mesh.h"
#include "io/obj/obj_error.h"
#include "io/obj_reader.h"

namespace rgbio::test {

// The ObjError read_obj_text throws for `text` (named "test.obj"); fails the test if none.
inline ObjError load_error(const std::string& text, const ReadOptions& options = {}) {
    try {
        read_obj_text(text, "test.obj", options);
    } catch (const ObjError& e) {
        return e;
    }
    ADD_FAILURE() << "expected an ObjError for:\n" << text;
    return ObjError(ObjProblem::Unreadable, "", 0, "no error");
}

// Whether some warning contains `part`.
inline bool has_warning(const std::vector<std::string>& warnings, const std::string& part) {
    for (const std::string& w : warnings)
        if (w.find(part) != std::string::npos) return true;
    return false;
}

// Triangles as triples of positions, rotated to start at the smallest, so that meshes can be
// compared regardless of vertex and face numbering.
using PositionTriangle = std::array<std::array<double, 3>, 3>;
inline std::multiset<PositionTriangle> triangles_by_position(const LoadedMesh& mesh) {
    std::multiset<PositionTriangle> set;
    for (const rgb::Triangle& t : mesh.triangles) {
        PositionTriangle p;
        for (int i = 0; i < 3; ++i) p[i] = {mesh.positions[t[i]].x, mesh.positions[t[i]].y, mesh.positions[t[i]].z};
        std::rotate(p.begin(), std::min_element(p.begin(), p.end()), p.end());
        set.insert(p);
    }
    return set;
}

// A closed octahedron (8 triangles, consistently oriented outwards).
inline const std::string kOctahedron =
    "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
    "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";

}  // namespace rgbio::test
