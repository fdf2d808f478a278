#pragma once
// Readable gtest output for the core's operator kinds (found by argument-dependent lookup).
#include <ostream>

#include "rgb/mesh/operators.h"

namespace rgb {

inline void PrintTo(SplitKind k, std::ostream* os) { *os << split_kind_name(k); }
inline void PrintTo(MergeKind k, std::ostream* os) { *os << merge_kind_name(k); }

}  // namespace rgb
