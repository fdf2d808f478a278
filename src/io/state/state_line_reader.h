#pragma once
// Reads the tokens of one "#rgb" state line (state_format.h), reporting problems as
// ObjError(BadState) with the file and line number.
#include <charconv>
#include <cstdint>
#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>

#include "io/obj/obj_error.h"
#include "io/obj/obj_parser.h"
#include "io/obj/printable_text.h"

namespace rgbio {

class StateLineReader {
public:
    StateLineReader(const ObjStateLine& line, const std::string& file) : rest_(line.text), line_(line.line), file_(file) {}

    std::string_view word() {
        skip_blanks();
        std::size_t e = 0;
        while (e < rest_.size() && !is_blank(rest_[e])) ++e;
        const std::string_view w = rest_.substr(0, e);
        rest_.remove_prefix(e);
        return w;
    }
    bool at_end() {
        skip_blanks();
        return rest_.empty();
    }
    template <class T>
    T number(T max = std::numeric_limits<T>::max()) {
        if constexpr (std::is_unsigned_v<T>) {
            // Up to 9 plain digits (a saved file's millions of indices and addresses), read in one
            // scan; anything else is read below, the same way, or named as a problem.
            skip_blanks();
            std::size_t e = 0;
            std::uint64_t value = 0;
            while (e < rest_.size() && e < 9 && rest_[e] >= '0' && rest_[e] <= '9') value = 10 * value + static_cast<std::uint64_t>(rest_[e++] - '0');
            if (e > 0 && (e == rest_.size() || is_blank(rest_[e])) && value <= max) {
                rest_.remove_prefix(e);
                return static_cast<T>(value);
            }
        }
        const std::string_view w = word();
        if (w.empty()) fail("the line ends too early (is the file truncated?)");
        T value{};
        const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), value);
        if constexpr (std::is_floating_point_v<T>) {
            if (ec == std::errc::result_out_of_range || (ec == std::errc() && std::abs(value) > kMaxCoordinate))
                fail("coordinate " + quoted_file_text(w) + " exceeds the supported magnitude 1e12");
        }
        if (ec != std::errc() || end != w.data() + w.size()) fail("expected a number, found " + quoted_file_text(w));
        if constexpr (std::is_floating_point_v<T>) {
            if (!std::isfinite(value)) fail("non-finite value");
        } else if (value > max) {
            fail("value " + std::string(w) + " is out of range (at most " + std::to_string(max) + ")");
        }
        return value;
    }
    // The rest of the line, blanks at its start skipped (a name that may hold spaces, last on its line).
    std::string_view rest() {
        skip_blanks();
        const std::string_view r = rest_;
        rest_ = {};
        return r;
    }
    void expect_end() {
        if (!at_end()) fail("unexpected trailing values");
    }
    [[noreturn]] void fail(const std::string& reason) const {
        throw ObjError(ObjProblem::BadState, file_, line_, "rgbsub state: " + reason);
    }

private:
    // Tested directly rather than searched for in a set: a saved file has millions of state numbers.
    static bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }
    void skip_blanks() {
        std::size_t b = 0;
        while (b < rest_.size() && is_blank(rest_[b])) ++b;
        rest_.remove_prefix(b);
    }

    std::string_view rest_;
    std::size_t line_;
    const std::string& file_;
};

}  // namespace rgbio
