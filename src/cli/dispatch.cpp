#include "cli/dispatch.h"

#include <algorithm>
#include <iostream>
#include <string_view>

#include "cli/commands.h"

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
        << commands[0].name << "\n\ncommands:\n";
    std::size_t name_width = 0;
    for (const Command& command : commands) name_width = std::max(name_width, command.name.size());
    for (const Command& command : commands) {
        out << "  " << command.name << std::string(name_width + 3 - command.name.size(), ' ')
            << command.description << '\n';
    }
    out << "\n'rgbsub COMMAND --help' describes a command's arguments.\n"
           "exit codes: 0 ok, 1 usage error, 2 bad input, 3 I/O failure\n";
}

int run_command(const Command& command, std::span<const std::string> args) {
    try {
        return command.run(args);
    } catch (const UsageError& error) {
        std::cerr << "rgbsub " << command.name << ": " << error.what() << "\n(see 'rgbsub " << command.name
                  << " --help')\n";
        return exit_usage;
    }
}

}  // namespace

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
    std::cerr << "rgbsub: unknown command '" << first << "'; 'rgbsub --help' lists the commands\n";
    return exit_usage;
}

}  // namespace cli
