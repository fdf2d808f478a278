#pragma once
// Numbers in OBJ text: reals read correctly rounded (std::from_chars) with the dialects exporters
// write, and 1-based (or negative, relative) element indices.
#include <cstdint>
#include <optional>
#include <string_view>
#include <variant>

namespace rgbio {

enum class RealProblem { NotANumber, Overflow };

// A token as a double. A leading '+' is accepted. Values too small for a double (1e-400) are
// read as 0 with their sign, as every C library does; only too-large ones are a problem.
std::variant<double, RealProblem> read_obj_real(std::string_view token);

enum class IndexProblem { NotAnInteger, Zero, OutOfRange };

// An OBJ index (1..count, or -1..-count counting back from the last element defined so far) as a
// 0-based index.
std::variant<std::uint32_t, IndexProblem> read_obj_index(std::string_view token, std::size_t count);

}  // namespace rgbio
