#include "io/obj/obj_numbers.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace rgbio {

namespace {

// Whether a decimal that std::from_chars found out of range is tiny (|x| < 1) rather than huge:
// the position of its first significant digit plus its exponent decides it, without locale-bound
// strtod.
bool is_underflow(std::string_view digits) {
    if (!digits.empty() && (digits[0] == '-' || digits[0] == '+')) digits.remove_prefix(1);
    const std::size_t exponent_at = std::min(digits.find_first_of("eE"), digits.size());
    const std::string_view mantissa = digits.substr(0, exponent_at);
    const std::size_t point = std::min(mantissa.find('.'), mantissa.size());
    const std::size_t first = mantissa.find_first_of("123456789");
    if (first == std::string_view::npos) return true;
    // |x| = 0.d... * 10^magnitude before the exponent is applied.
    long long magnitude = first < point ? static_cast<long long>(point - first) : -static_cast<long long>(first - point - 1);
    if (exponent_at < digits.size()) {
        std::string_view exponent = digits.substr(exponent_at + 1);
        if (!exponent.empty() && exponent[0] == '+') exponent.remove_prefix(1);
        long long value = 0;
        const auto [end, ec] = std::from_chars(exponent.data(), exponent.data() + exponent.size(), value);
        if (ec == std::errc::result_out_of_range) return exponent[0] == '-';
        magnitude += value;
    }
    return magnitude <= 0;
}

}  // namespace

std::variant<double, RealProblem> read_obj_real(std::string_view token) {
    // from_chars rejects the leading '+' that OBJ exporters sometimes write.
    std::string_view digits = token;
    if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-' && digits[1] != '+') digits.remove_prefix(1);
    double value = 0.0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (end != digits.data() + digits.size() || (ec != std::errc() && ec != std::errc::result_out_of_range))
        return RealProblem::NotANumber;
    if (ec == std::errc::result_out_of_range) {
        if (!is_underflow(digits)) return RealProblem::Overflow;
        return digits[0] == '-' ? -0.0 : 0.0;
    }
    return value;
}

std::variant<std::uint32_t, IndexProblem> read_obj_index(std::string_view token, std::size_t count) {
    long long value = 0;
    // Up to 18 plain digits (every index of a file below 4 GiB) are read here directly: a saved
    // file has millions of them, and from_chars is a call with more cases than these need.
    if (!token.empty() && token.size() <= 18 && std::all_of(token.begin(), token.end(), [](char c) { return c >= '0' && c <= '9'; })) {
        for (char c : token) value = 10 * value + (c - '0');
    } else {
        const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (token.empty() || end != token.data() + token.size() || (ec != std::errc() && ec != std::errc::result_out_of_range))
            return IndexProblem::NotAnInteger;
        if (ec == std::errc::result_out_of_range) return IndexProblem::OutOfRange;
    }
    if (value == 0) return IndexProblem::Zero;
    const long long resolved = value > 0 ? value - 1 : static_cast<long long>(count) + value;
    if (resolved < 0 || resolved >= static_cast<long long>(count)) return IndexProblem::OutOfRange;
    return static_cast<std::uint32_t>(resolved);
}

}  // namespace rgbio
