#pragma once
// A subcommand's command line split into positional words, switches (`--wireframe`) and options
// with a value (`--level 3` or `--level=3`). `--help` is always accepted as a switch. Short names
// (`-o` for `--output`) are aliases the command declares. After `--`, every word is positional
// (a file named `-x` is `-- -x` or `./-x`).
//
// Usage errors (UsageError, exit 1): an unknown option (`--nope`, `-x`), a switch given a value, an
// option without its value (also when the next word is itself an option: `-o -o`), and any option
// or switch given twice.
#include <initializer_list>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace cli {

class Arguments {
public:
    using ShortName = std::pair<std::string_view, std::string_view>;  // {"-o", "--output"}

    // Names include their dashes. Throws UsageError as described above.
    Arguments(std::span<const std::string> args, std::initializer_list<std::string_view> switches,
              std::initializer_list<std::string_view> options, std::initializer_list<ShortName> short_names = {});

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
