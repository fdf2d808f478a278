#include "cli/arguments.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/commands.h"

namespace {

using Words = std::vector<std::string>;

TEST(Arguments, SeparatesPositionalWordsSwitchesAndOptions) {
    const Words words{"in.obj", "--wireframe", "--level", "3", "out.obj", "--radius=0.5"};
    const cli::Arguments arguments(words, {"--wireframe"}, {"--level", "--radius"});
    EXPECT_EQ(arguments.positional(), (Words{"in.obj", "out.obj"}));
    EXPECT_TRUE(arguments.has("--wireframe"));
    EXPECT_EQ(arguments.value("--level"), "3");
    EXPECT_EQ(arguments.value("--radius"), "0.5");
    EXPECT_FALSE(arguments.has("--help"));
}

TEST(Arguments, AbsentOptionsGiveTheFallback) {
    const cli::Arguments arguments(Words{}, {}, {"--level", "--radius"});
    EXPECT_EQ(arguments.value("--level"), std::nullopt);
    EXPECT_EQ(arguments.integer("--level", 7, 0, 10), 7);
    EXPECT_EQ(arguments.number("--radius", 0.25), 0.25);
}

TEST(Arguments, HelpIsAlwaysAccepted) {
    const cli::Arguments arguments(Words{"--help"}, {}, {});
    EXPECT_TRUE(arguments.has("--help"));
}

TEST(Arguments, ParsesNumbers) {
    const cli::Arguments arguments(Words{"--level=-2", "--radius", "1.5e-1"}, {}, {"--level", "--radius"});
    EXPECT_EQ(arguments.integer("--level", 0, -5, 5), -2);
    EXPECT_EQ(arguments.number("--radius", 0.0), 0.15);
}

TEST(Arguments, RejectsMalformedCommandLines) {
    EXPECT_THROW(cli::Arguments(Words{"--nope"}, {}, {}), cli::UsageError);
    EXPECT_THROW(cli::Arguments(Words{"--level"}, {}, {"--level"}), cli::UsageError);
    EXPECT_THROW(cli::Arguments(Words{"--wireframe=1"}, {"--wireframe"}, {}), cli::UsageError);
}

TEST(Arguments, RejectsValuesThatAreNotNumbersInRange) {
    const cli::Arguments arguments(Words{"--level", "3x", "--depth", "11", "--radius", "nan"}, {},
                                   {"--level", "--depth", "--radius"});
    EXPECT_THROW(arguments.integer("--level", 0, 0, 10), cli::UsageError);
    EXPECT_THROW(arguments.integer("--depth", 0, 0, 10), cli::UsageError);
    EXPECT_THROW(arguments.number("--radius", 0.0), cli::UsageError);
}

}  // namespace
