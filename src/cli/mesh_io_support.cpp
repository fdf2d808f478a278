#include "cli/mesh_io_support.h"

#include <iostream>

#include "cli/commands.h"
#include "io/gltf_export.h"

namespace cli {

void print_warnings(const char* command, const std::string& file, const std::vector<std::string>& warnings) {
    for (const std::string& warning : warnings) std::cerr << "rgbsub " << command << ": " << file << ": warning: " << warning << '\n';
}

rgbio::LoadedAsset load_input(const char* command, const std::string& file, const Arguments& arguments) {
    std::vector<std::string> warnings;
    rgbio::LoadedAsset asset = rgbio::load_asset(file, &warnings, read_options(arguments));
    print_warnings(command, file, warnings);
    return asset;
}

void save_output(const char* command, const rgb::Mesh& mesh, const std::string& file, const rgbio::SaveOptions& save) {
    print_warnings(command, file, rgbio::dropped_attributes(mesh, save.attributes.get()));
    rgbio::save_mesh_file(mesh, file, save);
}

rgbio::ReadOptions read_options(const Arguments& arguments) { return {.strict = arguments.has(kStrictSwitch)}; }

rgbio::SavedPositions parse_positions(const std::string& value) {
    if (value == "display") return rgbio::SavedPositions::Displayed;
    if (value == "limit") return rgbio::SavedPositions::Limit;
    throw UsageError("--positions must be 'display' or 'limit', not '" + value + "'");
}

}  // namespace cli
