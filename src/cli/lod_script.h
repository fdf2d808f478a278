#pragma once
// The script language of `rgbsub apply`: one level-of-detail edit per line.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh.h"
#include "rgb/refine.h"

namespace cli {

// `level N [sphere X Y Z R]`, or `budget TRIANGLES`: the core's LOD driver refining the longest
// edges first until the budget (and trimming the finest vertices if the mesh is over it).
struct LodEdit {
    int level = 0;
    std::optional<std::size_t> budget;
    std::optional<std::pair<glm::dvec3, double>> sphere;  // centre, radius
    std::size_t line = 0;
    std::string text;  // the line as written, for --timings
};

// Throws ObjError-style messages "SCRIPT:LINE: reason" as rgbio::ObjError (Unreadable when the file
// cannot be read, Syntax for a bad line) so that the exit codes match those of mesh files.
std::vector<LodEdit> read_lod_script(const std::string& file);
std::vector<LodEdit> parse_lod_script(const std::string& text, const std::string& file);

rgb::SetLevelStats apply_lod_edit(rgb::Mesh& mesh, const LodEdit& edit);

}  // namespace cli
