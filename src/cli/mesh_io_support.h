#pragma once
// What the mesh commands (info, refine, apply, render, edit) share: `--strict`, printing loader
// warnings and reading `--positions`.
#include <string>
#include <string_view>
#include <vector>

#include "cli/arguments.h"
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

// "display" or "limit"; throws UsageError otherwise.
rgbio::SavedPositions parse_positions(const std::string& value);

}  // namespace cli
