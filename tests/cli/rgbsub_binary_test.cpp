// Runs the rgbsub executable and checks what a user sees: output and exit code.
#include <string>

#include <gtest/gtest.h>

#include "cli/commands.h"
#include "run_rgbsub.h"

namespace {

using cli_test::Outcome;
using cli_test::run_rgbsub;

TEST(RgbsubBinary, HelpListsEverySubcommandAndExitsZero) {
    const Outcome run = run_rgbsub({"--help"});
    EXPECT_EQ(run.exit_code, cli::exit_ok);
#define RGBSUB_EXPECT_LISTED(name, description) \
    EXPECT_NE(run.output.find("  " #name " "), std::string::npos) << run.output; \
    EXPECT_NE(run.output.find(description), std::string::npos) << run.output;
    RGBSUB_COMMANDS(RGBSUB_EXPECT_LISTED)
#undef RGBSUB_EXPECT_LISTED
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
