#pragma once
// Folder io/script: includes io/obj, io/files and the core.
// A set of levels of detail from one mesh (`rgbsub lods`): each level the canonical mesh of its
// request (a `level`, `budget` or `tolerance` script line, run by ScriptRunner on a copy of the input,
// so a function of the request alone), finest first; how far each written level is from the surface
// it stands for; when an engine should switch to it; and whether the levels nest.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "io/script/lod_script.h"

namespace rgbio {

enum class LodSetCriterion { Levels, Budgets, Tolerances };

// The option that asks for it: "--levels", "--budgets" or "--tolerances".
const char* lod_set_option(LodSetCriterion criterion);

// The requests a comma-separated list asks for (`4,3,1`, `20000,5000`, `0.1%,1%`), finest first:
// levels and budgets in decreasing order, tolerances by increasing world amount on `mesh` (a % of its
// bounding-box diagonal, as world_amount). Throws std::invalid_argument naming the bad entry for an
// empty list or entry, a value out of range (levels 0..kMaxLevel, budgets 1..500,000,000, tolerances
// positive) and a value given twice.
std::vector<ScriptLine> lod_set_requests(LodSetCriterion criterion, const std::string& list, const rgb::Mesh& mesh);

// The mesh of one request, made from `input` (not changed). Throws TooLarge (triangle_limit.h) when it
// would need more than max_triangles triangles.
rgb::Mesh lod_set_level(const rgb::Mesh& input, const ScriptLine& request, std::size_t max_triangles);

// The screen resolution and error the switch coverage assumes: a level is good enough while its error
// covers at most one pixel of a 1080-pixel-high view.
inline constexpr double kCoverageScreenPixels = 1080.0;

// MSFT_screencoverage for levels with these errors, finest first, on a mesh of this size (the base
// mesh's bounding-box diagonal): level i is shown down to the coverage at which level i+1's error
// spans one pixel, ((size / error[i+1]) / kCoverageScreenPixels)^2 (coverage is the share of the
// screen's area the mesh covers, the size spanning sqrt(coverage) of its height), at most 1 and at
// most the finer level's; the coarsest is shown down to 0 (never culled).
std::vector<double> switch_coverage(const std::vector<double>& errors, double size);

// Whether every position in `coarser` is one of `finer` (bit for bit). Both are sorted on the way.
bool positions_nested(std::vector<glm::dvec3> coarser, std::vector<glm::dvec3> finer);

// The file of level i of a set written to `output` as one file per level: OUT's stem, "_LOD" and i,
// OUT's extension, in OUT's folder (`lv.obj` -> `lv_LOD0.obj`).
std::string lod_file_name(const std::string& output, std::size_t level);

}  // namespace rgbio
