// Saved files edited or forged by hand. Every change after which the #rgb state describes another
// mesh than the file's v and f lines, or no RGB mesh in normal form at all, drops the state with a
// warning (the file then loads as the plain mesh its lines give); a change that keeps the mesh
// (numbering) restores it. Each expectation follows from what the change does to the mesh, not from
// what the loader happens to do.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/mesh_file.h"
#include "io/obj/number_format.h"
#include "io/obj_reader.h"
#include "obj_test_support.h"
#include "rgb/lod/requests.h"
#include "support/same_mesh.h"
#include "support/set_level.h"

namespace rgbio {
namespace {

// A mesh with four levels and green, red and blue faces: the faces around two base vertices refined
// once (the two faces touching both get two split edges: blue ones), and a small ball to level 3.
rgb::Mesh adaptive_octahedron() {
    rgb::Mesh mesh = build_mesh(read_obj_text(test::kOctahedron, "octahedron.obj"));
    rgbtest::set_level(mesh, 1, rgb::Sphere{{1, 0, 0}, 0.05});
    rgbtest::set_level(mesh, 1, rgb::Sphere{{0, 1, 0}, 0.05});
    rgbtest::set_level(mesh, 3, rgb::Sphere{{0.5, 0.3, 0.2}, 0.1});
    return mesh;
}

// A saved file as lines, with the address entries of its state (face a1 a2 level) pulled out so
// that tests can change them and write the lines back.
struct SavedFile {
    std::vector<std::string> lines;
    std::size_t first_v = 0, first_f = 0, first_address_line = 0, address_lines = 0;
    std::vector<std::array<std::uint64_t, 4>> addresses;

    explicit SavedFile(const std::string& text) {
        std::istringstream in(text);
        for (std::string line; std::getline(in, line);) lines.push_back(line);
        first_v = find("v ");
        first_f = find("f ");
        first_address_line = find("#rgb a ");
        for (std::size_t i = first_address_line; i < lines.size() && lines[i].starts_with("#rgb a "); ++i) {
            ++address_lines;
            std::istringstream numbers(lines[i].substr(7));
            for (std::array<std::uint64_t, 4> a; numbers >> a[0] >> a[1] >> a[2] >> a[3];) addresses.push_back(a);
        }
    }
    std::size_t find(const std::string& start) const {
        for (std::size_t i = 0; i < lines.size(); ++i)
            if (lines[i].starts_with(start)) return i;
        ADD_FAILURE() << "no line starts with '" << start << "'";
        return 0;
    }
    // The text, with the address lines written from `addresses` (8 per line, as rgbsub writes them).
    std::string text() const {
        std::string out;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            if (i == first_address_line) {
                for (std::size_t k = 0; k < addresses.size(); k += 8) {
                    out += "#rgb a";
                    for (std::size_t j = k; j < std::min(addresses.size(), k + 8); ++j)
                        for (std::uint64_t x : addresses[j]) out += ' ' + std::to_string(x);
                    out += '\n';
                }
            }
            if (i >= first_address_line && i < first_address_line + address_lines) continue;
            out += lines[i] + '\n';
        }
        return out;
    }
    // The corners (0-based) of face i, in the order of its f line.
    std::array<std::uint32_t, 3> face(std::size_t i) const {
        std::istringstream corners(lines[first_f + i].substr(2));
        std::array<std::uint32_t, 3> c{};
        for (std::uint32_t& v : c) corners >> v;
        for (std::uint32_t& v : c) --v;
        return c;
    }
    void set_face(std::size_t i, const std::array<std::uint32_t, 3>& c) {
        lines[first_f + i] = "f " + std::to_string(c[0] + 1) + " " + std::to_string(c[1] + 1) + " " + std::to_string(c[2] + 1);
    }
    std::size_t num_faces() const {
        std::size_t n = 0;
        while (first_f + n < lines.size() && lines[first_f + n].starts_with("f ")) ++n;
        return n;
    }
};

void expect_state_dropped(const std::string& text) {
    const LoadedMesh loaded = read_obj_text(text, "edited.obj");
    EXPECT_FALSE(loaded.adaptive) << "the state was used although it no longer describes the file";
    EXPECT_TRUE(test::has_warning(loaded.warnings, "does not match the file")) << (loaded.warnings.empty() ? "" : loaded.warnings[0]);
}

// Indices into SavedFile::addresses of two vertices with different levels, both above 0.
std::pair<std::size_t, std::size_t> two_levels(const SavedFile& file) {
    for (std::size_t i = 0; i < file.addresses.size(); ++i)
        for (std::size_t j = i + 1; j < file.addresses.size(); ++j)
            if (file.addresses[i][3] != file.addresses[j][3]) return {i, j};
    ADD_FAILURE() << "no two levels";
    return {0, 1};
}

// The f-line indices of two faces of the saved mesh that share the edge a-b, and their third corners.
struct EdgePair {
    std::size_t f, g;
    std::uint32_t a, b, x, y;  // f runs a->b, g runs b->a; x and y are opposite the edge
};

// Face pairs whose shared edge is the red edge of both (one red, one blue of one level: the two
// triangles of a parent with two split edges), or a green edge between two greens of one level.
std::vector<EdgePair> pairs(const rgb::Mesh& mesh, bool red_blue) {
    std::vector<std::uint32_t> line_of_face(mesh.face_capacity()), obj_vertex(mesh.vertex_capacity());
    std::uint32_t n = 0;
    for (rgb::FaceId f : mesh.faces()) line_of_face[f.idx] = n++;
    n = 0;
    for (rgb::VertexId v : mesh.vertices()) obj_vertex[v.idx] = n++;
    std::vector<EdgePair> found;
    for (rgb::FaceId f : mesh.faces())
        for (int c = 0; c < 3; ++c) {
            const rgb::HalfedgeId h = rgb::Mesh::halfedge(f, c), o = mesh.opposite(h);
            if (!o.valid()) continue;
            const rgb::FaceId g = rgb::Mesh::face(o);
            if (mesh.level(f) != mesh.level(g)) continue;
            const bool red_edge_of_both = mesh.colour(f) == rgb::Colour::Red && mesh.type(f).red_edge == c &&
                                          mesh.colour(g) == rgb::Colour::Blue && mesh.type(g).red_edge == rgb::Mesh::corner(o);
            const bool greens = mesh.colour(f) == rgb::Colour::Green && mesh.colour(g) == rgb::Colour::Green;
            if (red_blue ? red_edge_of_both : greens)
                found.push_back({line_of_face[f.idx], line_of_face[g.idx], obj_vertex[mesh.from_vertex(h).idx],
                                 obj_vertex[mesh.to_vertex(h).idx], obj_vertex[mesh.opposite_vertex(h).idx],
                                 obj_vertex[mesh.opposite_vertex(o).idx]});
        }
    return found;
}

// The quadrilateral a-y-b-x split along x-y instead of a-b.
void flip(SavedFile& file, const EdgePair& p) {
    file.set_face(p.f, {p.a, p.y, p.x});
    file.set_face(p.g, {p.y, p.b, p.x});
}

TEST(SavedStateTampering, TheUntouchedFileRestores) {
    const rgb::Mesh mesh = adaptive_octahedron();
    const LoadedMesh loaded = read_obj_text(SavedFile(format_obj(mesh, {})).text(), "saved.obj");
    ASSERT_TRUE(loaded.adaptive);
    EXPECT_TRUE(rgbtest::same_mesh(*loaded.adaptive, mesh));
}

// Found by the fuzz test: the state read with no faces at all (a null array copied). The header's
// counts, which would call the file truncated, are made unreadable as the fuzzer made them.
TEST(SavedStateTampering, AFileWithoutItsFaceLinesIsRefused) {
    SavedFile file(format_obj(adaptive_octahedron(), {}));
    std::erase_if(file.lines, [](const std::string& line) { return line.starts_with("f "); });
    ASSERT_TRUE(file.lines[0].starts_with("# rgbsub mesh: "));
    file.lines[0].insert(9, ";");
    try {
        read_obj_text(file.text(), "edited.obj");
        ADD_FAILURE() << "a file without faces loaded";
    } catch (const ObjError& e) {
        EXPECT_NE(std::string(e.what()).find("no faces"), std::string::npos) << e.what();
    }
}

TEST(SavedStateTampering, SwappedAddressesOfTwoLevelsAreDropped) {
    SavedFile file(format_obj(adaptive_octahedron(), {}));
    const auto [i, j] = two_levels(file);
    std::swap(file.addresses[i], file.addresses[j]);
    expect_state_dropped(file.text());
}

TEST(SavedStateTampering, EveryPairOfSwappedAddressesOfOneLevelIsDropped) {
    SavedFile file(format_obj(adaptive_octahedron(), {}));
    // Two vertices of one level trade places: the same vertex set, but the v lines (and the faces)
    // now name other points.
    std::size_t tried = 0;
    for (std::size_t i = 0; i + 1 < file.addresses.size(); ++i)
        for (std::size_t j = i + 1; j < file.addresses.size(); ++j)
            if (file.addresses[i][3] == file.addresses[j][3] && file.addresses[i] != file.addresses[j]) {
                SavedFile swapped = file;
                std::swap(swapped.addresses[i], swapped.addresses[j]);
                expect_state_dropped(swapped.text());
                ++tried;
                break;
            }
    EXPECT_GT(tried, 10u);
}

TEST(SavedStateTampering, ARepeatedAddressIsDropped) {
    SavedFile file(format_obj(adaptive_octahedron(), {}));
    file.addresses[5] = file.addresses[2];
    expect_state_dropped(file.text());
}

TEST(SavedStateTampering, AnAddressMovedToAnAbsentPointIsDropped) {
    SavedFile file(format_obj(adaptive_octahedron(), {}));
    // One step of a vertex's own level along a1 or a2, keeping the numerators odd-sum (still reduced)
    // and inside the face: a point of the same level that the file does not hold. The first vertex
    // above the base that has such a neighbour point.
    bool moved = false;
    for (std::size_t i = 0; i < file.addresses.size() && !moved; ++i) {
        std::array<std::uint64_t, 4>& a = file.addresses[i];
        if (a[3] == 0) continue;
        for (const std::array<std::uint64_t, 4>& candidate : {std::array<std::uint64_t, 4>{a[0], a[1] + 2, a[2], a[3]},
                                                               std::array<std::uint64_t, 4>{a[0], a[1], a[2] + 2, a[3]},
                                                               std::array<std::uint64_t, 4>{a[0], a[1] - 2, a[2], a[3]},
                                                               std::array<std::uint64_t, 4>{a[0], a[1], a[2] - 2, a[3]}}) {
            const bool inside = candidate[1] + candidate[2] <= (std::uint64_t(1) << candidate[3]) && candidate[1] < (1u << 30) &&
                                candidate[2] < (1u << 30);
            if (inside && std::find(file.addresses.begin(), file.addresses.end(), candidate) == file.addresses.end()) {
                a = candidate;
                moved = true;
                break;
            }
        }
    }
    ASSERT_TRUE(moved);
    expect_state_dropped(file.text());
}

TEST(SavedStateTampering, AnUnreducedAddressIsDropped) {
    SavedFile file(format_obj(adaptive_octahedron(), {}));
    std::array<std::uint64_t, 4>& a = file.addresses[0];
    a = {a[0], 2 * a[1], 2 * a[2], a[3] + 1};  // the same point, written one level finer
    expect_state_dropped(file.text());
}

TEST(SavedStateTampering, TheOtherDiagonalOfANormalFormQuadIsDropped) {
    const rgb::Mesh mesh = adaptive_octahedron();
    const SavedFile file(format_obj(mesh, {}));
    const std::vector<EdgePair> quads = pairs(mesh, true);
    ASSERT_FALSE(quads.empty());
    // The same vertices and positions, a valid RGB triangulation, but not the normal form the core
    // keeps (docs/requests.md "What a request means"): only that check sees it.
    for (const EdgePair& quad : quads) {
        SavedFile flipped = file;
        flip(flipped, quad);
        expect_state_dropped(flipped.text());
    }
}

TEST(SavedStateTampering, AFlippedEdgeBetweenGreensIsDropped) {
    const rgb::Mesh mesh = adaptive_octahedron();
    const std::vector<EdgePair> greens = pairs(mesh, false);
    ASSERT_GT(greens.size(), 5u);
    for (std::size_t k = 0; k < greens.size(); k += greens.size() / 5) {
        SavedFile file(format_obj(mesh, {}));
        flip(file, greens[k]);
        expect_state_dropped(file.text());
    }
}

TEST(SavedStateTampering, TwoTrianglesJoinedIntoAQuadAreDropped) {
    const rgb::Mesh mesh = adaptive_octahedron();
    SavedFile file(format_obj(mesh, {}));
    // Another program merged two triangles into the quadrilateral they form, and kept the header's
    // face count true.
    const EdgePair pair = pairs(mesh, false).front();
    file.lines[file.first_f + pair.f] = "f " + std::to_string(pair.a + 1) + " " + std::to_string(pair.y + 1) + " " +
                                        std::to_string(pair.b + 1) + " " + std::to_string(pair.x + 1);
    file.lines[file.first_f + pair.g] = "# f removed";
    const std::string count = std::to_string(mesh.num_faces()) + " triangles";
    file.lines[0].replace(file.lines[0].find(count), count.size(), std::to_string(mesh.num_faces() - 1) + " triangles");
    const LoadedMesh loaded = read_obj_text(file.text(), "quad.obj");
    EXPECT_FALSE(loaded.adaptive);
    EXPECT_TRUE(test::has_warning(loaded.warnings, "a face with 4 vertices (line " + std::to_string(file.first_f + pair.f + 1) + ")"))
        << (loaded.warnings.empty() ? "" : loaded.warnings[0]);
}

TEST(SavedStateTampering, LabelsAndTextureCoordinatesAddedElsewhereKeepTheState) {
    const rgb::Mesh mesh = adaptive_octahedron();
    SavedFile file(format_obj(mesh, {}));
    // Another program added a material and a texture coordinate for one face: the mesh is the same.
    file.lines[file.first_f - 1] += "\nvt 0.25 0.75\nusemtl shiny";
    const auto c = file.face(2);
    file.lines[file.first_f + 2] = "f " + std::to_string(c[0] + 1) + "/1 " + std::to_string(c[1] + 1) + "/1 " + std::to_string(c[2] + 1) + "/1";
    const LoadedMesh loaded = read_obj_text(file.text(), "labelled.obj");
    ASSERT_TRUE(loaded.adaptive) << (loaded.warnings.empty() ? "" : loaded.warnings[0]);
    EXPECT_TRUE(rgbtest::same_mesh(*loaded.adaptive, mesh));
    EXPECT_EQ(loaded.face_materials.names, std::vector<std::string>{"shiny"});
    EXPECT_EQ(loaded.face_materials.of_triangle, std::vector<std::uint32_t>(mesh.num_faces(), 0u));
    EXPECT_EQ(loaded.texcoords, std::vector<glm::dvec2>{glm::dvec2(0.25, 0.75)});
    ASSERT_EQ(loaded.triangle_texcoords.size(), mesh.num_faces());
    for (std::size_t t = 0; t < mesh.num_faces(); ++t) {
        const std::uint32_t want = t == 2 ? 0 : kNoIndex;
        EXPECT_EQ(loaded.triangle_texcoords[t], (std::array<std::uint32_t, 3>{want, want, want})) << "triangle " << t;
    }
}

TEST(SavedStateTampering, ACoordinateOneUlpOffIsDropped) {
    SavedFile file(format_obj(adaptive_octahedron(), {}));
    const LoadedMesh original = read_obj_text(file.text(), "saved.obj");
    const std::size_t vertex = original.positions.size() / 2;
    glm::dvec3 p = original.positions[vertex];
    p.y = std::nextafter(p.y, 10.0);
    std::string line = "v";
    for (int i = 0; i < 3; ++i) append_double(line, p[i]);
    file.lines[file.first_v + vertex] = line;
    const LoadedMesh loaded = read_obj_text(file.text(), "edited.obj");
    EXPECT_FALSE(loaded.adaptive);
    EXPECT_TRUE(test::has_warning(loaded.warnings, "1 of " + std::to_string(original.positions.size()) + " vertex positions differ"));
    EXPECT_EQ(loaded.positions[vertex], p);
}

TEST(SavedStateTampering, AMovedBaseVertexIsDropped) {
    SavedFile file(format_obj(adaptive_octahedron(), {}));
    const std::size_t line = file.find("#rgb p ");
    file.lines[line] = "#rgb p 1.5 0 0";  // was 1 0 0; the v lines still show the old surface
    expect_state_dropped(file.text());
}

TEST(SavedStateTampering, ConsistentlyRenumberedVerticesRestore) {
    const rgb::Mesh mesh = adaptive_octahedron();
    SavedFile file(format_obj(mesh, {}));
    // Another program swapped two non-base vertices everywhere: v lines, face corners and addresses
    // alike. The mesh is the same; only its numbering changed.
    const std::size_t n0 = 6, i = n0 + 3, j = n0 + 11;
    std::swap(file.lines[file.first_v + i], file.lines[file.first_v + j]);
    std::swap(file.addresses[i - n0], file.addresses[j - n0]);
    for (std::size_t f = 0; f < file.num_faces(); ++f) {
        auto c = file.face(f);
        for (std::uint32_t& v : c) v = v == i ? static_cast<std::uint32_t>(j) : v == j ? static_cast<std::uint32_t>(i) : v;
        file.set_face(f, c);
    }
    const LoadedMesh loaded = read_obj_text(file.text(), "renumbered.obj");
    ASSERT_TRUE(loaded.adaptive) << (loaded.warnings.empty() ? "" : loaded.warnings[0]);
    EXPECT_TRUE(rgbtest::same_mesh(*loaded.adaptive, mesh));
}

}  // namespace
}  // namespace rgbio
