#include "support/checked_operators.h"

#include <gtest/gtest.h>

#include "rgb/values/loop_split.h"
#include "support/operator_printing.h"

namespace rgbtest {

rgb::VertexId split_checked(rgb::Mesh& mesh, rgb::VertexId a, rgb::VertexId b, rgb::SplitKind expected) {
    const rgb::HalfedgeId h = mesh.find_edge(a, b);
    EXPECT_TRUE(h.valid()) << "no edge " << a.idx << "-" << b.idx;
    EXPECT_EQ(rgb::split_kind(mesh, h), expected) << "edge " << a.idx << "-" << b.idx;
    return rgb::split_edge(mesh, h);
}

}  // namespace rgbtest
