// Runs the rgbsub executable and checks what a user sees: output and exit code.
#include <sys/wait.h>

#include <cstdio>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "cli/commands.h"

namespace {

struct Outcome {
    int exit_code;
    std::string output;  // stdout and stderr together
};

Outcome run_rgbsub(const std::string& arguments, const std::string& environment = "") {
    const std::string command = environment + " '" RGBSUB_BINARY "' " + arguments + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (pipe == nullptr) throw std::runtime_error("cannot run " + command);
    Outcome run{-1, {}};
    char buffer[4096];
    while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) run.output.append(buffer, n);
    const int status = pclose(pipe);
    if (WIFEXITED(status)) run.exit_code = WEXITSTATUS(status);
    return run;
}

TEST(RgbsubBinary, HelpListsEverySubcommandAndExitsZero) {
    const Outcome run = run_rgbsub("--help");
    EXPECT_EQ(run.exit_code, cli::exit_ok);
#define RGBSUB_EXPECT_LISTED(name, description) \
    EXPECT_NE(run.output.find("  " #name " "), std::string::npos) << run.output; \
    EXPECT_NE(run.output.find(description), std::string::npos) << run.output;
    RGBSUB_COMMANDS(RGBSUB_EXPECT_LISTED)
#undef RGBSUB_EXPECT_LISTED
}

TEST(RgbsubBinary, UnknownSubcommandExitsOneNamingIt) {
    const Outcome run = run_rgbsub("frobnicate");
    EXPECT_EQ(run.exit_code, cli::exit_usage);
    EXPECT_NE(run.output.find("unknown command 'frobnicate'"), std::string::npos) << run.output;
}

TEST(RgbsubBinary, UnknownOptionOfASubcommandExitsOne) {
    const Outcome run = run_rgbsub("edit --no-such-option", "env -u DISPLAY");
    EXPECT_EQ(run.exit_code, cli::exit_usage);
    EXPECT_NE(run.output.find("--no-such-option"), std::string::npos) << run.output;
}

TEST(RgbsubBinary, EditWithoutDisplayExitsTwoNamingTheHeadlessAlternative) {
    const Outcome run = run_rgbsub("", "env -u DISPLAY");
    EXPECT_EQ(run.exit_code, cli::exit_bad_input);
    EXPECT_NE(run.output.find("rgbsub render"), std::string::npos) << run.output;
}

}  // namespace
