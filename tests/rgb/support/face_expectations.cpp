#include "support/face_expectations.h"

#include <algorithm>
#include <ostream>

namespace rgbtest {
namespace {

std::string describe(const ExpectedFace& e) {
    std::string s = std::string(rgb::colour_name(e.colour)) + std::to_string(e.level) + "(" + std::to_string(e.v[0].idx) +
                    "," + std::to_string(e.v[1].idx) + "," + std::to_string(e.v[2].idx) + ")";
    if (e.red) s += " red " + std::to_string(e.red->first.idx) + "-" + std::to_string(e.red->second.idx);
    return s;
}

std::string describe(const rgb::Mesh& mesh, rgb::FaceId f) {
    const auto& v = mesh.face_vertices(f);
    const rgb::FaceType& t = mesh.type(f);
    std::string s = std::string(rgb::colour_name(t.colour)) + std::to_string(t.level) + "(" + std::to_string(v[0].idx) +
                    "," + std::to_string(v[1].idx) + "," + std::to_string(v[2].idx) + ")";
    if (t.colour != rgb::Colour::Green)
        s += " red " + std::to_string(v[t.red_edge].idx) + "-" + std::to_string(v[(t.red_edge + 1) % 3].idx);
    return s;
}

bool same_cycle(const std::array<rgb::VertexId, 3>& x, const std::array<rgb::VertexId, 3>& y) {
    for (int r = 0; r < 3; ++r)
        if (x[0] == y[r] && x[1] == y[(r + 1) % 3] && x[2] == y[(r + 2) % 3]) return true;
    return false;
}

bool matches(const rgb::Mesh& mesh, rgb::FaceId f, const ExpectedFace& e) {
    const rgb::FaceType& t = mesh.type(f);
    if (t.colour != e.colour || t.level != e.level) return false;
    if (t.colour == rgb::Colour::Green) return true;
    const auto& v = mesh.face_vertices(f);
    const rgb::VertexId p = v[t.red_edge], q = v[(t.red_edge + 1) % 3];
    return (p == e.red->first && q == e.red->second) || (p == e.red->second && q == e.red->first);
}

std::string all_faces(const rgb::Mesh& mesh) {
    std::string s;
    for (rgb::FaceId f : mesh.faces()) s += "\n  " + describe(mesh, f);
    return s;
}

}  // namespace

ExpectedFace green(int level, rgb::VertexId a, rgb::VertexId b, rgb::VertexId c) {
    return {{a, b, c}, rgb::Colour::Green, level, std::nullopt};
}
ExpectedFace red(int level, rgb::VertexId a, rgb::VertexId b, rgb::VertexId c, rgb::VertexId red_a, rgb::VertexId red_b) {
    return {{a, b, c}, rgb::Colour::Red, level, std::pair{red_a, red_b}};
}
ExpectedFace blue(int level, rgb::VertexId a, rgb::VertexId b, rgb::VertexId c, rgb::VertexId red_a, rgb::VertexId red_b) {
    return {{a, b, c}, rgb::Colour::Blue, level, std::pair{red_a, red_b}};
}

testing::AssertionResult has_faces(const rgb::Mesh& mesh, const std::vector<ExpectedFace>& expected) {
    for (const ExpectedFace& e : expected) {
        rgb::FaceId found;
        for (rgb::FaceId f : mesh.faces())
            if (same_cycle(mesh.face_vertices(f), e.v)) found = f;
        if (!found.valid()) return testing::AssertionFailure() << "no face " << describe(e) << "; faces:" << all_faces(mesh);
        if (!matches(mesh, found, e))
            return testing::AssertionFailure() << "expected " << describe(e) << ", found " << describe(mesh, found);
    }
    return testing::AssertionSuccess();
}

testing::AssertionResult faces_are(const rgb::Mesh& mesh, const std::vector<ExpectedFace>& expected) {
    if (auto r = has_faces(mesh, expected); !r) return r;
    if (mesh.num_faces() != expected.size())
        return testing::AssertionFailure() << mesh.num_faces() << " faces, expected " << expected.size() << ":"
                                           << all_faces(mesh);
    return testing::AssertionSuccess();
}

ColourCounts colour_counts(const rgb::Mesh& mesh) {
    ColourCounts c;
    for (rgb::FaceId f : mesh.faces()) {
        switch (mesh.colour(f)) {
            case rgb::Colour::Green: ++c.green; break;
            case rgb::Colour::Red: ++c.red; break;
            case rgb::Colour::Blue: ++c.blue; break;
        }
    }
    return c;
}

void PrintTo(const ColourCounts& c, std::ostream* os) { *os << c.green << " G / " << c.red << " R / " << c.blue << " B"; }

}  // namespace rgbtest
