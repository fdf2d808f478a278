#pragma once
// A set of levels of detail made and written as `rgbsub lods` does it, for the CLI and the editor's
// Export LODs panel alike: each level the canonical mesh of its request (script/lod_set.h), its error
// against the surface it stands for, its switch coverage and whether it nests in the finer level;
// written as one glTF file (MSFT_lod) or one file per level.
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "io/mesh_file.h"
#include "io/script/lod_set.h"
#include "rgb/mesh/mesh.h"

namespace rgbio {

struct LodSetLevel {
    LodSetLevel(ScriptLine made_for, rgb::Mesh made) : request(std::move(made_for)), mesh(std::move(made)) {}

    ScriptLine request;
    rgb::Mesh mesh;
    std::vector<glm::dvec3> positions;  // as written: the live vertices in slot order
    double error = 0.0;                 // see docs/cli.md#lods
    double coverage = 0.0;              // MSFT_screencoverage
    bool nested = false;                // every vertex is one of the finer level's (LOD0: false)
};

struct LodSet {
    std::vector<LodSetLevel> levels;  // finest first
    double size = 0.0;                // the base mesh's bounding-box diagonal
    // Notes on what was written ("LOD2: <glTF normal repair>").
    std::vector<std::string> warnings;
};

struct LodSetOptions {
    SaveOptions save;  // the positions and what rides on the base mesh (its progress is not used)
    std::size_t max_triangles = 0;
    // Where to write the set (glTF: one file; else lod_file_name's, each written as it is made);
    // none: only make it. A set that fails part way removes the files it wrote.
    std::optional<std::string> output;
    // Told before each step: making level i of n ("LOD<i>"), then measuring the errors (i == n); the
    // coarser levels are made beside LOD0, on another thread, and told of once LOD0 and they are
    // made. Called on the caller's thread only. Returning false stops the work: make_lod_set throws
    // LodSetStopped.
    std::function<bool(std::size_t step, std::size_t levels)> progress;
};

struct LodSetStopped : std::runtime_error {
    LodSetStopped() : std::runtime_error("stopped") {}
};

// The positions a set is written with unless told otherwise: the limit positions, which put a vertex
// at the same point in every level; a cage's detail positions (displayed), the same in every level
// too and the surface it carries.
SavedPositions lod_set_positions(const rgb::Mesh& input);

// The sizes a request can be checked for ahead (levels and budgets), for all levels before any
// work: throws TooLarge (script/triangle_limit.h).
void check_lod_set_size(const rgb::Mesh& input, const std::vector<ScriptLine>& requests, std::size_t max_triangles);

// The set of `requests` (lod_set_requests, finest first) made from `input` (not changed). Throws
// TooLarge, SaveError and what the work throws, with nothing of the set left on disk.
LodSet make_lod_set(const rgb::Mesh& input, const std::vector<ScriptLine>& requests, const LodSetOptions& options);

}  // namespace rgbio
