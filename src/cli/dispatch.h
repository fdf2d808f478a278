#pragma once
// Picks the subcommand named by the first argument and runs it.
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace cli {

// args excludes the program name; returns the process exit code (see commands.h).
int dispatch(std::span<const std::string> args);

// What `command` prints when memory runs out: std::bad_alloc (`error` null) or a size beyond what a
// container can hold (std::length_error). A command that saves adds that nothing was saved; info,
// which saves nothing, does not.
std::string out_of_memory_message(std::string_view command, const std::length_error* error);

}  // namespace cli
