#include "io/obj/number_format.h"

#include <charconv>

namespace rgbio {

void append_double(std::string& out, double x) {
    char buffer[32];  // the longest shortest form, e.g. -2.2250738585072014e-308, has 24 characters
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
    out += ' ';
    out.append(buffer, result.ptr);
}

void append_digits(std::string& out, std::uint64_t x) {
    char buffer[20];  // 18446744073709551615 has 20 digits
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
    out.append(buffer, result.ptr);
}

void append_integer(std::string& out, std::uint64_t x) {
    out += ' ';
    append_digits(out, x);
}

}  // namespace rgbio
