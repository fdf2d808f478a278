#pragma once
// Doubles in text, exactly: shortest round-trip form (std::to_chars), locale-independent.
#include <string>

namespace rgbio {

// Appends ' ' and the shortest decimal that reads back (with std::from_chars) as exactly x.
void append_double(std::string& out, double x);

}  // namespace rgbio
