#include "cli/arguments.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "cli/commands.h"

namespace cli {
namespace {

bool contains(std::initializer_list<std::string_view> names, std::string_view name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

template <class T>
T parse_number(std::string_view option, const std::string& text) {
    T parsed{};
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, parsed);
    if (text.empty() || error != std::errc() || stop != end) {
        throw UsageError(std::string(option) + " expects a number, got '" + text + "'");
    }
    return parsed;
}

// "-x", "--name": an option. A lone "-" (a conventional file name) and negative numbers ("-2",
// "-.5,30" for --view) are values.
bool looks_like_option(const std::string& word) {
    if (word.size() < 2 || word[0] != '-') return false;
    return !(std::isdigit(static_cast<unsigned char>(word[1])) || word[1] == '.');
}

}  // namespace

Arguments::Arguments(std::span<const std::string> args, std::initializer_list<std::string_view> switches,
                     std::initializer_list<std::string_view> options, std::initializer_list<ShortName> short_names) {
    const auto long_name_of = [&](const std::string& word) {
        for (const auto& [short_name, long_name] : short_names)
            if (word == short_name) return std::string(long_name);
        return word;
    };
    const auto spelled = [&](const std::string& name) {
        for (const auto& [short_name, long_name] : short_names)
            if (name == long_name) return std::string(short_name) + "/" + name;
        return name;
    };
    bool only_positional = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& word = args[i];
        if (only_positional || !looks_like_option(word)) {
            positional_.push_back(word);
            continue;
        }
        if (word == "--") {
            only_positional = true;
            continue;
        }
        const std::size_t equals = word.starts_with("--") ? word.find('=') : std::string::npos;
        const std::string name = long_name_of(word.substr(0, equals));
        if (named_.contains(name)) throw UsageError(spelled(name) + " is given twice");
        if (name == "--help" || contains(switches, name)) {
            if (equals != std::string::npos) throw UsageError(name + " takes no value");
            named_[name] = std::nullopt;
        } else if (contains(options, name)) {
            if (equals != std::string::npos) {
                named_[name] = word.substr(equals + 1);
            } else if (i + 1 < args.size() && !looks_like_option(args[i + 1])) {
                named_[name] = args[++i];
            } else if (i + 1 < args.size()) {
                throw UsageError(spelled(name) + " needs a value, but the next word is the option '" + args[i + 1] +
                                 "' (a value that starts with '-' is written " + name + "=VALUE)");
            } else {
                throw UsageError(spelled(name) + " needs a value");
            }
        } else {
            throw UsageError("unknown option " + word.substr(0, equals));
        }
    }
}

bool Arguments::has(std::string_view name) const { return named_.contains(name); }

std::optional<std::string> Arguments::value(std::string_view option) const {
    const auto found = named_.find(option);
    return found == named_.end() ? std::nullopt : found->second;
}

long Arguments::integer(std::string_view option, long fallback, long min, long max) const {
    const std::optional<std::string> text = value(option);
    if (!text) return fallback;
    const long parsed = parse_number<long>(option, *text);
    if (parsed < min || parsed > max) {
        throw UsageError(std::string(option) + " must be between " + std::to_string(min) + " and " +
                         std::to_string(max) + ", got " + *text);
    }
    return parsed;
}

double Arguments::number(std::string_view option, double fallback) const {
    const std::optional<std::string> text = value(option);
    if (!text) return fallback;
    const double parsed = parse_number<double>(option, *text);
    if (!std::isfinite(parsed)) throw UsageError(std::string(option) + " must be finite, got " + *text);
    return parsed;
}

}  // namespace cli
