#pragma once
// A subcommand's command line split into positional words, switches (`--wireframe`) and options
// with a value (`--level 3` or `--level=3`). `--help` is always accepted as a switch.
#include <initializer_list>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace cli {

class Arguments {
public:
    // Names include their dashes. Throws UsageError for an unknown `--name`, a switch given a
    // value or an option missing its value.
    Arguments(std::span<const std::string> args, std::initializer_list<std::string_view> switches,
              std::initializer_list<std::string_view> options);

    const std::vector<std::string>& positional() const { return positional_; }
    bool has(std::string_view name) const;
    std::optional<std::string> value(std::string_view option) const;
    // The option's value as a number, or fallback when absent; throws UsageError naming the
    // option when the value is not entirely a number in [min, max].
    long integer(std::string_view option, long fallback, long min, long max) const;
    double number(std::string_view option, double fallback) const;

private:
    std::vector<std::string> positional_;
    std::map<std::string, std::optional<std::string>, std::less<>> named_;
};

}  // namespace cli
