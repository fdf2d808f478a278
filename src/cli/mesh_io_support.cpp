#include "cli/mesh_io_support.h"

#include <iostream>

#include "cli/commands.h"

namespace cli {

void print_warnings(const char* command, const std::string& file, const std::vector<std::string>& warnings) {
    for (const std::string& warning : warnings) std::cerr << "rgbsub " << command << ": " << file << ": warning: " << warning << '\n';
}

rgbio::ReadOptions read_options(const Arguments& arguments) { return {.strict = arguments.has(kStrictSwitch)}; }

rgbio::SavedPositions parse_positions(const std::string& value) {
    if (value == "display") return rgbio::SavedPositions::Displayed;
    if (value == "limit") return rgbio::SavedPositions::Limit;
    throw UsageError("--positions must be 'display' or 'limit', not '" + value + "'");
}

}  // namespace cli
