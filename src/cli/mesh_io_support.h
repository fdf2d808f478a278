#pragma once
// What the mesh commands (info, refine, apply) share: printing loader warnings and reading
// `--positions`.
#include <string>
#include <vector>

#include "io/mesh_file.h"

namespace cli {

void print_warnings(const char* command, const std::string& file, const std::vector<std::string>& warnings);

// "display" or "limit"; throws UsageError otherwise.
rgbio::SavedPositions parse_positions(const std::string& value);

}  // namespace cli
