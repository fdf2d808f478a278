// The saved state's format (state_format.h): at most half again the size of the file's v and f lines
// whatever the refinement (issue 11), the base mesh taken from the body where the body has it, and
// files of the previous version still read.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "io/mesh_file.h"
#include "io/obj/number_format.h"
#include "io/obj_reader.h"
#include "obj_test_support.h"
#include "rgb/lod/requests.h"
#include "support/same_mesh.h"
#include "support/set_level.h"

namespace rgbio {
namespace {

// A closed torus of m x n quads cut into triangles: a base mesh with many vertices, so that a state
// repeating it would be as large as the body.
std::string torus_obj(int m, int n) {
    std::string text;
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < n; ++j) {
            const double u = 2 * std::numbers::pi * i / m, v = 2 * std::numbers::pi * j / n;
            text += 'v';
            for (double x : {(1 + 0.35 * std::cos(v)) * std::cos(u), (1 + 0.35 * std::cos(v)) * std::sin(u), 0.35 * std::sin(v)})
                append_double(text, x);
            text += '\n';
        }
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < n; ++j) {
            const int a = i * n + j + 1, b = (i + 1) % m * n + j + 1, c = (i + 1) % m * n + (j + 1) % n + 1, d = i * n + (j + 1) % n + 1;
            text += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + "\n";
            text += "f " + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(d) + "\n";
        }
    return text;
}

rgb::Mesh torus() { return build_mesh(read_obj_text(torus_obj(24, 16), "torus.obj")); }

// The torus refined to level 3 in a small ball: most base vertices and faces untouched.
rgb::Mesh refined_torus() {
    rgb::Mesh mesh = torus();
    rgbtest::set_level(mesh, 3, rgb::Sphere{{1.35, 0, 0}, 0.2});
    return mesh;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

void expect_restores(const std::string& text, const rgb::Mesh& mesh) {
    const LoadedMesh loaded = read_obj_text(text, "saved.obj");
    ASSERT_TRUE(loaded.adaptive) << (loaded.warnings.empty() ? "" : loaded.warnings[0]);
    EXPECT_TRUE(rgbtest::same_mesh(*loaded.adaptive, mesh));
}

// The file's size over the size of its v, vt, vn and f lines.
double size_over_body(const std::string& text) {
    std::size_t body = 0;
    for (const std::string& line : lines_of(text))
        if (line.starts_with("v ") || line.starts_with("vt ") || line.starts_with("vn ") || line.starts_with("f ")) body += line.size() + 1;
    return static_cast<double>(text.size()) / static_cast<double>(body);
}

// The same file in format version 2, which lists every base vertex and face: each p-as-v and t-as-f
// record replaced by the lines it stands for, written from the v and f lines' own text.
std::string as_version_2(const std::string& text) {
    const std::vector<std::string> lines = lines_of(text);
    std::vector<std::string> v_lines, f_lines;
    for (const std::string& line : lines) {
        if (line.starts_with("v ")) v_lines.push_back(line.substr(2));
        if (line.starts_with("f ")) f_lines.push_back(line.substr(2));
    }
    std::string out;
    std::size_t base_vertex = 0;
    for (const std::string& line : lines) {
        std::istringstream words(line);
        std::string tag, kind;
        words >> tag >> kind;
        if (line == "#rgb state 3") {
            out += "#rgb state 2\n";
        } else if (kind == "p") {
            ++base_vertex;
            out += line + '\n';
        } else if (kind == "p-as-v") {
            std::size_t count = 0;
            words >> count;
            for (std::size_t k = 0; k < count; ++k) out += "#rgb p " + v_lines[base_vertex++] + '\n';
        } else if (kind == "t-as-f") {
            std::size_t first = 0, count = 0;
            words >> first >> count;
            for (std::size_t k = 0; k < count; ++k) {
                std::istringstream corners(f_lines[first + k]);
                out += "#rgb t";
                for (std::size_t c; corners >> c;) out += ' ' + std::to_string(c - 1);
                out += '\n';
            }
        } else {
            out += line + '\n';
        }
    }
    return out;
}

TEST(StateFormat, TheFileIsAtMostHalfAgainItsVAndFLines) {
    rgb::Mesh unrefined = torus(), in_a_ball = torus(), everywhere = torus(), deep_in_a_ball = torus();
    rgbtest::set_level(in_a_ball, 2, rgb::Sphere{{1.35, 0, 0}, 0.2});
    rgbtest::set_level(everywhere, 2);
    rgbtest::set_level(deep_in_a_ball, 6, rgb::Sphere{{0, 1.35, 0}, 0.05});
    for (const rgb::Mesh* mesh : {&unrefined, &in_a_ball, &everywhere, &deep_in_a_ball})
        EXPECT_LE(size_over_body(format_obj(*mesh, {})), 1.5) << mesh->num_faces() << " faces";
    // Where the base mesh is in the body, the state hardly adds to it.
    EXPECT_LT(size_over_body(format_obj(unrefined, {})), 1.02);
    // Limit positions never give the base positions, which the state then lists: a little-refined
    // file grows by about the size of its base vertices' v lines, a well refined one stays small.
    EXPECT_LE(size_over_body(format_obj(everywhere, {.positions = SavedPositions::Limit})), 1.5);
}

TEST(StateFormat, UntouchedBaseVerticesAndFacesAreTakenFromTheBody) {
    const rgb::Mesh mesh = refined_torus();
    const std::string text = format_obj(mesh, {});
    EXPECT_NE(text.find("#rgb p-as-v "), std::string::npos);
    EXPECT_NE(text.find("#rgb t-as-f "), std::string::npos);
    expect_restores(text, mesh);
}

TEST(StateFormat, FilesOfVersion2StillRestore) {
    const rgb::Mesh mesh = refined_torus();
    const std::string old = as_version_2(format_obj(mesh, {}));
    ASSERT_EQ(old.find("-as-"), std::string::npos);
    ASSERT_NE(old.find("#rgb state 2\n"), std::string::npos);
    expect_restores(old, mesh);
}

TEST(StateFormat, BaseFacesTakenFromOtherFLinesAreDropped) {
    const rgb::Mesh mesh = refined_torus();
    std::string text = format_obj(mesh, {});
    // Every run shifted by one face: a different base mesh, whose surface the v lines do not show.
    std::string shifted;
    for (const std::string& line : lines_of(text)) {
        std::istringstream words(line);
        std::string tag, kind;
        std::size_t first = 0, count = 0;
        words >> tag >> kind >> first >> count;
        shifted += (kind == "t-as-f" ? "#rgb t-as-f " + std::to_string(first + 1) + " " + std::to_string(count) : line) + '\n';
    }
    ASSERT_NE(shifted, text);
    const LoadedMesh loaded = read_obj_text(shifted, "shifted.obj");
    EXPECT_FALSE(loaded.adaptive);
    EXPECT_TRUE(test::has_warning(loaded.warnings, "does not match the file")) << (loaded.warnings.empty() ? "" : loaded.warnings[0]);
}

TEST(StateFormat, SwappedLinesOfUntouchedBaseFacesStillRestore) {
    const rgb::Mesh mesh = refined_torus();
    std::vector<std::string> lines = lines_of(format_obj(mesh, {}));
    // Two untouched base faces that the state takes from consecutive f lines, and that no vertex
    // address names. Another program swapped the two lines: the state then numbers these base faces
    // the other way round, which changes nothing else, and the file's mesh comes back.
    std::vector<std::size_t> named;  // base faces that some address names
    std::size_t base_face = 0, first_f = 0;
    std::optional<std::pair<std::size_t, std::size_t>> pair;  // (base face, f line index) of the first of the two
    for (const std::string& line : lines) {
        if (first_f == 0 && line.starts_with("f ")) first_f = static_cast<std::size_t>(&line - lines.data());
        std::istringstream words(line);
        std::string tag, kind;
        words >> tag >> kind;
        if (kind == "t") {
            for (std::size_t a, b, c; words >> a >> b >> c;) ++base_face;
        } else if (kind == "t-as-f") {
            std::size_t first = 0, count = 0;
            words >> first >> count;
            if (!pair && count >= 2) pair = {base_face, first};
            base_face += count;
        } else if (kind == "a") {
            for (std::size_t face, a1, a2, level; words >> face >> a1 >> a2 >> level;) named.push_back(face);
        }
    }
    ASSERT_TRUE(pair);
    for (std::size_t f : {pair->first, pair->first + 1}) ASSERT_EQ(std::count(named.begin(), named.end(), f), 0);
    std::swap(lines[first_f + pair->second], lines[first_f + pair->second + 1]);
    std::string text;
    for (const std::string& l : lines) text += l + '\n';
    expect_restores(text, mesh);
}

TEST(StateFormat, AMoveOfAnUntouchedBaseVertexIsKept) {
    const rgb::Mesh mesh = refined_torus();
    std::vector<std::string> lines = lines_of(format_obj(mesh, {}));
    // Base vertex 200 lies on the far side of the torus, shown at level 0: its v line is its base
    // position, and moving it elsewhere moves the restored base vertex with it (the edit wins).
    const std::size_t first_v = 1, vertex = 200;
    ASSERT_TRUE(lines[first_v + vertex].starts_with("v "));
    const LoadedMesh original = read_obj_text(format_obj(mesh, {}), "saved.obj");
    ASSERT_GT(glm::distance(original.positions[vertex], glm::dvec3(1.35, 0, 0)), 1.0);
    const glm::dvec3 moved = original.positions[vertex] + glm::dvec3(0, 0, 0.125);
    std::string line = "v";
    for (int i = 0; i < 3; ++i) append_double(line, moved[i]);
    lines[first_v + vertex] = line;
    std::string text;
    for (const std::string& l : lines) text += l + '\n';
    const LoadedMesh loaded = read_obj_text(text, "moved.obj");
    ASSERT_TRUE(loaded.adaptive) << (loaded.warnings.empty() ? "" : loaded.warnings[0]);
    EXPECT_EQ(loaded.adaptive->base().position(vertex), moved);
    EXPECT_EQ(loaded.positions[vertex], moved);
}

TEST(StateFormat, ARunLongerThanItsSectionIsAnError) {
    const rgb::Mesh mesh = refined_torus();
    const std::string text = format_obj(mesh, {});
    const std::size_t at = text.find("#rgb p-as-v ");
    ASSERT_NE(at, std::string::npos);
    const std::size_t end = text.find('\n', at);
    const std::string longer = text.substr(0, at) + "#rgb p-as-v " + std::to_string(std::stoul(text.substr(at + 12, end - at - 12)) + 1) + text.substr(end);
    const ObjError e = test::load_error(longer);
    EXPECT_EQ(e.problem(), ObjProblem::BadState);
    EXPECT_NE(e.reason().find("section 'base-vertices' announces"), std::string::npos) << e.what();
}

// The address lines of a large mesh are read in parallel blocks of lines (state_format.cpp); a
// problem is still reported at its own line, and of two, the first in the file.
TEST(StateFormat, TheFirstBrokenAddressLineIsNamedInALongSection) {
    rgb::Mesh mesh = torus();
    rgbtest::set_level(mesh, 4);  // 768 * 4^4 faces, half as many vertices: over 10,000 address lines
    const std::string text = format_obj(mesh, {});
    std::vector<std::size_t> address_starts;  // offsets of the "#rgb a " lines
    for (std::size_t at = text.find("\n#rgb a "); at != std::string::npos; at = text.find("\n#rgb a ", at + 1))
        address_starts.push_back(at + 1);
    ASSERT_GT(address_starts.size(), 10000u);
    // Breaks the first number of the address line at `offset`; gives the line's 1-based number.
    auto break_line = [](std::string& file, std::size_t offset) {
        file[offset + 7] = 'x';
        return static_cast<std::size_t>(std::count(file.begin(), file.begin() + static_cast<std::ptrdiff_t>(offset), '\n')) + 1;
    };
    const std::size_t early = address_starts[address_starts.size() / 4], late = address_starts[3 * address_starts.size() / 4];
    std::string late_only = text;
    const std::size_t late_line = break_line(late_only, late);
    const ObjError late_error = test::load_error(late_only);
    EXPECT_EQ(late_error.problem(), ObjProblem::BadState);
    EXPECT_EQ(late_error.line(), late_line) << late_error.what();
    std::string both = late_only;
    const std::size_t early_line = break_line(both, early);
    const ObjError first_error = test::load_error(both);
    EXPECT_EQ(first_error.line(), early_line) << first_error.what();
    EXPECT_NE(first_error.reason().find("expected a number, found 'x"), std::string::npos) << first_error.what();
}

}  // namespace
}  // namespace rgbio
