#include "cli/dispatch.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "cli/commands.h"
#include "io/formats/mesh_format.h"
#include "io/obj/obj_error.h"
#include "io/script/triangle_limit.h"

namespace cli {
namespace {

struct Command {
    std::string_view name;
    std::string_view description;
    int (*run)(std::span<const std::string>);
};

#define RGBSUB_COMMAND_ENTRY(name, description) Command{#name, description, run_##name},
constexpr Command commands[] = {RGBSUB_COMMANDS(RGBSUB_COMMAND_ENTRY)};
#undef RGBSUB_COMMAND_ENTRY

void print_help(std::ostream& out) {
    out << "rgbsub: paint level of detail onto a triangle mesh with RGB subdivision (exact Loop)\n\n"
           "usage: rgbsub [COMMAND] [ARGS...]    without a COMMAND: rgbsub "
        << commands[0].name << "\n       rgbsub FILE.obj [ARGS...]  is  rgbsub " << commands[0].name << " FILE.obj [ARGS...]\n\ncommands:\n";
    std::size_t name_width = 0;
    for (const Command& command : commands) name_width = std::max(name_width, command.name.size());
    for (const Command& command : commands) {
        out << "  " << command.name << std::string(name_width + 3 - command.name.size(), ' ')
            << command.description << '\n';
    }
    out << "\n'rgbsub COMMAND --help' describes a command's arguments.\n"
           "exit codes: 0 ok, 1 usage error, 2 bad input, 3 I/O or resource failure\n";
}

int run_command(const Command& command, std::span<const std::string> args) {
    const auto fail = [&](int code, const std::string& message) {
        std::cerr << "rgbsub " << command.name << ": " << message << '\n';
        return code;
    };
    try {
        return command.run(args);
    } catch (const UsageError& error) {
        return fail(exit_usage, std::string(error.what()) + "\n(see 'rgbsub " + std::string(command.name) + " --help')");
    } catch (const rgbio::ObjError& error) {
        return fail(error.problem() == rgbio::ObjProblem::Unreadable ? exit_io_failure : exit_bad_input, error.what());
    } catch (const rgbio::SaveError& error) {
        return fail(exit_io_failure, error.what());
    } catch (const rgbio::TooLarge& error) {
        return fail(exit_io_failure, std::string("refused: ") + error.what());
    } catch (const std::bad_alloc&) {
        return fail(exit_io_failure, out_of_memory_message(command.name, nullptr));
    } catch (const std::length_error& error) {
        return fail(exit_io_failure, out_of_memory_message(command.name, &error));
    } catch (const std::system_error& error) {
        return fail(exit_io_failure, std::string("the system refused a resource: ") + error.what());
    } catch (const std::exception& error) {
        return fail(exit_bad_input, error.what());
    }
}

// Whether a first word that is no command names a mesh for the editor: an existing file (not a
// folder), or a name with a mesh file's extension (which the editor then reports if it cannot read).
bool names_a_mesh(const std::string& word) {
    std::error_code error;
    return rgbio::has_mesh_extension(word) || std::filesystem::is_regular_file(word, error);
}

}  // namespace

std::string out_of_memory_message(std::string_view command, const std::length_error* error) {
    std::string message = error ? std::string("out of memory: a size beyond what this machine can hold (") + error->what() + ")"
                                : "out of memory: the request needs more memory than the system would give";
    // info writes nothing, so it has nothing to say about what was saved.
    return command == "info" ? message : message + "; nothing was saved";
}

int dispatch(std::span<const std::string> args) {
    if (args.empty()) return run_command(commands[0], args);
    const std::string& first = args.front();
    if (first == "--help" || first == "-h" || first == "help") {
        print_help(std::cout);
        return exit_ok;
    }
    for (const Command& command : commands) {
        if (command.name == first) return run_command(command, args.subspan(1));
    }
    // `rgbsub FILE.obj [ARGS...]` as `rgbsub` alone: the editor.
    if (names_a_mesh(first)) return run_command(commands[0], args);
    std::cerr << "rgbsub: unknown command '" << first << "'; 'rgbsub --help' lists the commands\n";
    return exit_usage;
}

}  // namespace cli
