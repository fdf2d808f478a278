#pragma once
// The subcommands of the `rgbsub` executable. Each one lives in command_<name>.cpp and defines
//     int cli::run_<name>(std::span<const std::string> args)
// where args are the words after the subcommand's name. To add one, write that file and add one
// line to RGBSUB_COMMANDS below: it both declares run_<name> and lists it in `rgbsub --help`.
#include <span>
#include <stdexcept>
#include <string>

namespace cli {

// Exit codes shared by every subcommand. Commands return exit_ok and report every failure by
// throwing; the dispatcher (dispatch.cpp) turns the exception into the code, in one place:
inline constexpr int exit_ok = 0;
inline constexpr int exit_usage = 1;       // UsageError: a malformed command line
inline constexpr int exit_bad_input = 2;   // rgbio::ObjError (but Unreadable), any other std::exception:
                                           // the input (file, environment) cannot be used
inline constexpr int exit_io_failure = 3;  // ObjError Unreadable, rgbio::SaveError, and resources the
                                           // system could not give: std::bad_alloc, std::length_error,
                                           // std::system_error

// Thrown for a malformed command line; the dispatcher prints it with a pointer to --help and
// exits with exit_usage.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// X(name, one-line description); the first entry is what `rgbsub` runs without a subcommand.
#define RGBSUB_COMMANDS(X) \
    X(edit, "open the editor on an OBJ mesh (the default when no subcommand is given)") \
    X(render, "render an OBJ mesh to a PNG headless (no display needed)") \
    X(info, "validate an OBJ file and print its counts, topology and RGB make-up") \
    X(refine, "set the level of detail of an OBJ mesh (everywhere or in a sphere) and save it") \
    X(apply, "run a script of level-of-detail edits on an OBJ mesh and save it") \
    X(remesh, "make a coarse cage of a dense OBJ mesh that keeps its detail, and save it") \
    X(lods, "write a set of levels of detail (glTF with MSFT_lod, or a file per level)")

#define RGBSUB_DECLARE_COMMAND(name, description) int run_##name(std::span<const std::string> args);
RGBSUB_COMMANDS(RGBSUB_DECLARE_COMMAND)
#undef RGBSUB_DECLARE_COMMAND

}  // namespace cli
