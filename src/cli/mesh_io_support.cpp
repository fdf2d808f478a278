#include "cli/mesh_io_support.h"

#include <iostream>

#include "cli/commands.h"
#include "io/obj_error.h"

namespace cli {

std::vector<std::string> with_long_output_option(std::span<const std::string> args) {
    std::vector<std::string> expanded(args.begin(), args.end());
    for (std::string& word : expanded)
        if (word == "-o") word = "--output";
    return expanded;
}

int report_io_errors(const char* command, const std::function<int()>& body) {
    try {
        return body();
    } catch (const rgbio::ObjError& error) {
        std::cerr << "rgbsub " << command << ": " << error.what() << '\n';
        return error.problem() == rgbio::ObjProblem::Unreadable ? exit_io_failure : exit_bad_input;
    } catch (const rgbio::SaveError& error) {
        std::cerr << "rgbsub " << command << ": " << error.what() << '\n';
        return exit_io_failure;
    }
}

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
