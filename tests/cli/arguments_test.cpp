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

// The UsageError text for `words`, or "" if they parse.
std::string usage_error(const Words& words) {
    try {
        const cli::Arguments arguments(words, {"--wire"}, {"--output", "--level", "--view"}, {{"-o", "--output"}});
    } catch (const cli::UsageError& e) {
        return e.what();
    }
    return "";
}

TEST(Arguments, ShortNamesAreAliases) {
    const cli::Arguments arguments(Words{"in.obj", "-o", "out.obj"}, {}, {"--output"}, {{"-o", "--output"}});
    EXPECT_EQ(arguments.value("--output"), "out.obj");
    EXPECT_EQ(arguments.positional(), (Words{"in.obj"}));
}

TEST(Arguments, RepeatedOptionsAreUsageErrors) {
    EXPECT_EQ(usage_error({"-o", "a.obj", "-o", "b.obj"}), "-o/--output is given twice");
    EXPECT_EQ(usage_error({"--output=a.obj", "-o", "b.obj"}), "-o/--output is given twice");
    EXPECT_EQ(usage_error({"--level", "1", "--level=2"}), "--level is given twice");
    EXPECT_EQ(usage_error({"--wire", "--wire"}), "--wire is given twice");
}

// `-o -o` used to write a file named "--output": an option's value cannot be another option.
TEST(Arguments, AnOptionIsNotAnotherOptionsValue) {
    EXPECT_EQ(usage_error({"in.obj", "-o", "-o"}),
              "-o/--output needs a value, but the next word is the option '-o' (a value that starts with '-' is written --output=VALUE)");
    EXPECT_EQ(usage_error({"--level", "--wire"}),
              "--level needs a value, but the next word is the option '--wire' (a value that starts with '-' is written --level=VALUE)");
    EXPECT_EQ(usage_error({"-o"}), "-o/--output needs a value");
    const cli::Arguments explicit_value(Words{"--output=-o"}, {}, {"--output"}, {{"-o", "--output"}});
    EXPECT_EQ(explicit_value.value("--output"), "-o");
}

TEST(Arguments, NegativeNumbersAndLoneDashAreValues) {
    const cli::Arguments arguments(Words{"--level", "-2", "--view", "-.5,30", "-"}, {}, {"--level", "--view"});
    EXPECT_EQ(arguments.value("--level"), "-2");
    EXPECT_EQ(arguments.value("--view"), "-.5,30");
    EXPECT_EQ(arguments.positional(), (Words{"-"}));
}

TEST(Arguments, UnknownShortAndLongOptionsAreNamed) {
    EXPECT_EQ(usage_error({"in.obj", "-x"}), "unknown option -x");
    EXPECT_EQ(usage_error({"--nope=3"}), "unknown option --nope");
    EXPECT_EQ(usage_error({"-output", "x"}), "unknown option -output");
}

TEST(Arguments, DoubleDashEndsTheOptions) {
    const cli::Arguments arguments(Words{"--level", "2", "--", "-x.obj", "--level", "--"}, {}, {"--level"});
    EXPECT_EQ(arguments.positional(), (Words{"-x.obj", "--level", "--"}));
    EXPECT_EQ(arguments.value("--level"), "2");
}

}  // namespace
