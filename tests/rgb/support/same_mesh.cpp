#include "support/same_mesh.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <tuple>
#include <vector>

#include "rgb/values/loop_geometry.h"

namespace rgbtest {

namespace {

using Bits = std::array<std::uint64_t, 3>;

Bits bits(const glm::dvec3& p) {
    Bits b;
    std::memcpy(b.data(), &p, sizeof p);
    return b;
}

struct FaceKey {
    std::array<Bits, 3> corners;  // rotated to start at the smallest
    int colour, level, red_edge;  // red edge relative to that rotation (0 for green)
    auto operator<=>(const FaceKey&) const = default;
};

std::vector<FaceKey> face_keys(const rgb::Mesh& mesh) {
    std::vector<FaceKey> keys;
    keys.reserve(mesh.num_faces());
    for (rgb::FaceId f : mesh.faces()) {
        std::array<Bits, 3> c;
        for (int i = 0; i < 3; ++i) c[i] = bits(rgb::displayed_position(mesh, mesh.face_vertices(f)[i]));
        const int first = static_cast<int>(std::min_element(c.begin(), c.end()) - c.begin());
        std::rotate(c.begin(), c.begin() + first, c.end());
        const rgb::FaceType t = mesh.type(f);
        const int red = t.colour == rgb::Colour::Green ? 0 : (t.red_edge - first + 3) % 3;
        keys.push_back({c, static_cast<int>(t.colour), t.level, red});
    }
    std::sort(keys.begin(), keys.end());
    return keys;
}

}  // namespace

testing::AssertionResult same_mesh(const rgb::Mesh& a, const rgb::Mesh& b) {
    if (a.num_vertices() != b.num_vertices() || a.num_faces() != b.num_faces())
        return testing::AssertionFailure() << a.num_vertices() << " vertices, " << a.num_faces() << " faces vs "
                                           << b.num_vertices() << " vertices, " << b.num_faces() << " faces";
    const std::vector<FaceKey> x = face_keys(a), y = face_keys(b);
    const auto [ix, iy] = std::mismatch(x.begin(), x.end(), y.begin());
    if (ix != x.end()) {
        double first[3];
        std::memcpy(first, ix->corners[0].data(), sizeof first);
        return testing::AssertionFailure() << "face " << (ix - x.begin()) << " of " << x.size()
                                           << " (sorted by position) differs: first corner at (" << first[0] << ", " << first[1]
                                           << ", " << first[2] << "), colour " << ix->colour << " level " << ix->level << " vs colour "
                                           << iy->colour << " level " << iy->level;
    }
    return testing::AssertionSuccess();
}

std::set<BaseSpacePoint> base_space_vertex_set(const rgb::Mesh& mesh) {
    std::set<BaseSpacePoint> points;
    for (rgb::VertexId v : mesh.vertices()) {
        const glm::dvec3 p = mesh.base_space_position(v);
        points.insert({p.x, p.y, p.z});
    }
    return points;
}

}  // namespace rgbtest
