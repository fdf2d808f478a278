#pragma once
// What the mesh commands (info, refine, apply) share: `-o` as the short form of `--output`,
// turning io errors into messages and exit codes, and printing loader warnings.
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "io/mesh_file.h"

namespace cli {

// args with every "-o" replaced by "--output" (Arguments only knows long options).
std::vector<std::string> with_long_output_option(std::span<const std::string> args);

// Runs body; an ObjError, SaveError or TooLarge is printed as "rgbsub COMMAND: message" and becomes
// exit_io_failure (unreadable input, failed save, a request too large for the machine) or
// exit_bad_input (anything wrong in a file).
int report_io_errors(const char* command, const std::function<int()>& body);

void print_warnings(const char* command, const std::string& file, const std::vector<std::string>& warnings);

// "display" or "limit"; throws UsageError otherwise.
rgbio::SavedPositions parse_positions(const std::string& value);

}  // namespace cli
