#pragma once
// What the mesh commands (info, refine, apply, render, edit) share: `--strict`, printing loader
// warnings, reading `--positions`, the crease options `--sharp-angle` and `--boundary`, and
// `--uv-interpolation` for the commands that save.
#include <memory>
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
    "  (the mesh read may be .obj, .gltf/.glb, .ply, .stl, .fbx, .dae, .3ds, .off or any other format\n"
    "  Assimp reads; what each brings is in docs/files.md)\n"
    "  --strict            refuse a non-manifold input (bow-tie vertices, edges of more than two faces)\n"
    "                      with exit code 2 instead of cutting it apart into a manifold\n";

// The crease options every command that reads a mesh accepts, and their lines for --help.
inline constexpr std::string_view kSharpAngleOption = "--sharp-angle";
inline constexpr std::string_view kBoundaryOption = "--boundary";
inline constexpr std::string_view kSharpHelp =
    "  --sharp-angle DEG   also tag as infinitely sharp (a crease) every interior base edge whose two\n"
    "                      face normals differ by more than DEG degrees (0-180; a flat edge has 0)\n"
    "  --boundary edge-only|edge-and-corner\n"
    "                      OpenSubdiv's boundary rule: edge-and-corner keeps boundary vertices with a\n"
    "                      single face fixed (default: the file's, else edge-only)\n";

// How texture coordinates are subdivided (rgb/values/uv_layout.h), for the commands that save a mesh.
inline constexpr std::string_view kUvInterpolationOption = "--uv-interpolation";
inline constexpr std::string_view kUvHelp =
    "  --uv-interpolation none|corners|boundaries|all\n"
    "                      how texture coordinates (vt) are subdivided, as OpenSubdiv's FVAR_LINEAR_*:\n"
    "                      none moves every UV but those a sharp feature pins (seams become smooth\n"
    "                      curves), corners keeps UV corners (one-triangle spans) in place, boundaries\n"
    "                      keeps seams and borders on their input lines, all is linear over each input\n"
    "                      triangle\n"
    "                      (default: the file's, else corners)\n";

// The input's UV layout over its (retagged) base mesh, with --uv-interpolation in place of the file's
// option when given; nullptr for a file without texture coordinates. Throws UsageError for a bad value.
std::shared_ptr<const rgb::UvLayout> input_uv_layout(const Arguments& arguments, const rgbio::LoadedAsset& asset);

// The mesh with the tags these options add to its base mesh's (the file's t lines or saved state);
// the mesh itself when neither is given. Throws UsageError for a bad value.
rgb::Mesh with_sharp_options(const Arguments& arguments, rgb::Mesh mesh);

// How to read the input mesh given the command's arguments (which must accept kStrictSwitch).
rgbio::ReadOptions read_options(const Arguments& arguments);

void print_warnings(const char* command, const std::string& file, const std::vector<std::string>& warnings);

// Reads `file` with the command's --strict, printing the loader's warnings, and adds the tags of
// --sharp-angle and --boundary (with_sharp_options).
rgbio::LoadedAsset load_input(const char* command, const std::string& file, const Arguments& arguments);

// Refuses (rgbio::SaveError) an output that cannot be saved, before any work: what
// rgbio::resolve_save_target refuses, and a folder that is not there or not writable.
void check_output_first(const std::string& file);

// For a glTF output, what the input alone says about it, before any work: positions that 32-bit floats
// cannot hold are refused (std::invalid_argument, exit code 2); material names and colours that glTF
// cannot hold are printed as warnings (the writer substitutes them). Nothing for other outputs.
void check_gltf_output_first(const char* command, const std::string& output, const rgbio::LoadedAsset& asset);

// Saves `mesh` with what rides on its base (save.attributes) to `file` in the format of its extension
// (io/formats/mesh_format.h). First prints, as warnings, what the save leaves out (the adaptive state
// in any format but OBJ, unless --plain asked for none).
void save_output(const char* command, const rgb::Mesh& mesh, const std::string& file, const rgbio::SaveOptions& save);

// The help lines of the output options refine and apply share.
inline constexpr std::string_view kOutputHelp =
    "  -o OUT              OUT.obj keeps the adaptive state (and the input's materials, groups, objects and\n"
    "                      smoothing groups); OUT.glb or OUT.gltf writes glTF 2.0 (positions, limit normals,\n"
    "                      materials, texture coordinates while the mesh is at level 0); OUT.ply (binary, doubles),\n"
    "                      OUT.stl (binary, floats), OUT.vtu (VTK XML) and OUT.msh (Gmsh 4.1) write the mesh\n"
    "                      with each face's level and RGB colour (and in .vtu/.msh its quality), without the\n"
    "                      adaptive state\n"
    "  --normals           OBJ: vn lines with the exact normals of the Loop limit surface\n";

// The switch of the commands that write .msh files (refine, apply, lods), its line for --help, and the
// encoding it asks for: binary with it, which wants a .msh output (UsageError with any other, where it
// would do nothing), else ASCII.
inline constexpr std::string_view kMshBinarySwitch = "--msh-binary";
inline constexpr std::string_view kMshBinaryHelp =
    "  --msh-binary        OUT.msh in Gmsh 4.1 binary (raw doubles, smaller, no decimals to parse) instead of ASCII\n";
rgbio::MshEncoding msh_encoding(const Arguments& arguments, const std::string& output);

// "display" or "limit"; throws UsageError otherwise.
rgbio::SavedPositions parse_positions(const std::string& value);

}  // namespace cli
