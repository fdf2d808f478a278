#pragma once
// Doubles in text, exactly: shortest round-trip form (std::to_chars), locale-independent.
#include <cstdint>
#include <string>

namespace rgbio {

// Appends ' ' and the shortest decimal that reads back (with std::from_chars) as exactly x.
void append_double(std::string& out, double x);
// Appends the decimal digits of x.
void append_digits(std::string& out, std::uint64_t x);
// Appends ' ' and the decimal digits of x.
void append_integer(std::string& out, std::uint64_t x);

}  // namespace rgbio
