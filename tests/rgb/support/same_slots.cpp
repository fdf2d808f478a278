#include "support/same_slots.h"

#include <algorithm>
#include <cstring>

namespace rgbtest {

namespace {

bool same_bits(const glm::dvec3& p, const glm::dvec3& q) { return std::memcmp(&p, &q, sizeof p) == 0; }

testing::AssertionResult liveness_differs(const char* what, std::uint32_t slot, bool live_in_a) {
    return testing::AssertionFailure() << what << " slot " << slot << " is " << (live_in_a ? "live" : "dead") << " vs "
                                       << (live_in_a ? "dead" : "live");
}

}  // namespace

testing::AssertionResult same_slots(const rgb::Mesh& a, const rgb::Mesh& b) {
    const std::size_t faces = std::max(a.face_capacity(), b.face_capacity());
    for (std::uint32_t i = 0; i < faces; ++i) {
        const rgb::FaceId f(i);
        if (a.is_live(f) != b.is_live(f)) return liveness_differs("face", i, a.is_live(f));
        if (!a.is_live(f)) continue;
        if (a.face_vertices(f) != b.face_vertices(f) || a.type(f) != b.type(f))
            return testing::AssertionFailure() << "face slot " << i << " has other corners or another type";
        for (int c = 0; c < 3; ++c)
            if (a.opposite(rgb::Mesh::halfedge(f, c)) != b.opposite(rgb::Mesh::halfedge(f, c)))
                return testing::AssertionFailure() << "face slot " << i << " has another neighbour across edge " << c;
    }
    const std::size_t vertices = std::max(a.vertex_capacity(), b.vertex_capacity());
    for (std::uint32_t i = 0; i < vertices; ++i) {
        const rgb::VertexId v(i);
        if (a.is_live(v) != b.is_live(v)) return liveness_differs("vertex", i, a.is_live(v));
        if (!a.is_live(v)) continue;
        if (a.level(v) != b.level(v) || a.is_boundary(v) != b.is_boundary(v) || !(a.address(v) == b.address(v)) ||
            !same_bits(a.insertion_position(v), b.insertion_position(v)))
            return testing::AssertionFailure() << "vertex slot " << i << " differs (level " << a.level(v) << " vs " << b.level(v) << ")";
    }
    if (a.num_faces() != b.num_faces() || a.num_vertices() != b.num_vertices())
        return testing::AssertionFailure() << "the live counts differ";
    return testing::AssertionSuccess();
}

}  // namespace rgbtest
