#pragma once
// What the mesh commands (info, refine, apply, render, edit) share: `--strict`, printing loader
// warnings and reading `--positions`.
#include <string>
#include <string_view>
#include <vector>

#include "cli/arguments.h"
#include "io/base_attributes.h"
#include "io/mesh_file.h"

namespace cli {

// The switch every command that reads a mesh accepts, and its line for the command's --help.
inline constexpr std::string_view kStrictSwitch = "--strict";
inline constexpr std::string_view kStrictHelp =
    "  --strict            refuse a non-manifold input (bow-tie vertices, edges of more than two faces)\n"
    "                      with exit code 2 instead of cutting it apart into a manifold\n";

// How to read the input mesh given the command's arguments (which must accept kStrictSwitch).
rgbio::ReadOptions read_options(const Arguments& arguments);

void print_warnings(const char* command, const std::string& file, const std::vector<std::string>& warnings);

// Reads `file` with the command's --strict, printing the loader's warnings.
rgbio::LoadedAsset load_input(const char* command, const std::string& file, const Arguments& arguments);

// Saves `mesh` with what rides on its base (save.attributes) to `file`: glTF for .glb/.gltf, OBJ
// otherwise. First prints, as warnings, what the save leaves out.
void save_output(const char* command, const rgb::Mesh& mesh, const std::string& file, const rgbio::SaveOptions& save);

// The help lines of the output options refine and apply share.
inline constexpr std::string_view kOutputHelp =
    "  -o OUT              OUT.obj keeps the adaptive state (and the input's materials, groups, objects and\n"
    "                      smoothing groups); OUT.glb or OUT.gltf writes glTF 2.0 (positions, limit normals,\n"
    "                      materials, texture coordinates while the mesh is at level 0)\n"
    "  --normals           OBJ: vn lines with the exact normals of the Loop limit surface\n";

// "display" or "limit"; throws UsageError otherwise.
rgbio::SavedPositions parse_positions(const std::string& value);

}  // namespace cli
