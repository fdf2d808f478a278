// Runs the rgbsub executable and checks what a user sees: output and exit code.
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/commands.h"
#include "run_rgbsub.h"

namespace {

using cli_test::Outcome;
using cli_test::run_rgbsub;

// The commands the README documents, written out here rather than taken from the table that prints
// the help: a command missing from the help, or one the README does not know, fails.
TEST(RgbsubBinary, HelpListsEverySubcommandAndExitsZero) {
    const Outcome run = run_rgbsub({"--help"});
    EXPECT_EQ(run.exit_code, cli::exit_ok);
    const std::string header = "commands:\n";
    const std::size_t start = run.output.find(header);
    ASSERT_NE(start, std::string::npos) << run.output;
    // One "  NAME   description" line per command, up to the blank line.
    std::vector<std::string> listed;
    std::istringstream lines(run.output.substr(start + header.size()));
    for (std::string line; std::getline(lines, line) && !line.empty();) {
        ASSERT_EQ(line.rfind("  ", 0), 0u) << line;
        std::istringstream words(line);
        std::string name, description;
        words >> name;
        std::getline(words >> std::ws, description);
        EXPECT_FALSE(description.empty()) << name << " has a description";
        listed.push_back(name);
    }
    EXPECT_EQ(listed, (std::vector<std::string>{"edit", "render", "info", "refine", "apply", "remesh", "lods"}));
    EXPECT_NE(run.output.find("without a COMMAND: rgbsub edit"), std::string::npos) << run.output;
}

TEST(RgbsubBinary, UnknownSubcommandExitsOneNamingIt) {
    const Outcome run = run_rgbsub({"frobnicate"});
    EXPECT_EQ(run.exit_code, cli::exit_usage);
    EXPECT_NE(run.output.find("unknown command 'frobnicate'"), std::string::npos) << run.output;
}

TEST(RgbsubBinary, UnknownOptionOfASubcommandExitsOne) {
    const Outcome run = run_rgbsub({"edit", "--no-such-option"}, "env -u DISPLAY");
    EXPECT_EQ(run.exit_code, cli::exit_usage);
    EXPECT_NE(run.output.find("--no-such-option"), std::string::npos) << run.output;
}

TEST(RgbsubBinary, EditWithoutDisplayExitsTwoNamingTheHeadlessAlternative) {
    const Outcome run = run_rgbsub({}, "env -u DISPLAY");
    EXPECT_EQ(run.exit_code, cli::exit_bad_input);
    EXPECT_NE(run.output.find("rgbsub render"), std::string::npos) << run.output;
}

}  // namespace
