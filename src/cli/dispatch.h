#pragma once
// Picks the subcommand named by the first argument and runs it.
#include <span>
#include <string>

namespace cli {

// args excludes the program name; returns the process exit code (see commands.h).
int dispatch(std::span<const std::string> args);

}  // namespace cli
