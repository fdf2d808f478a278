// Saving and loading rgb::Mesh: plain OBJ loads as a base mesh, saved files restore the adaptive
// state bit for bit, and further edits then give identical results to never having saved.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <tiny_obj_loader.h>

#include "io/files/atomic_file.h"
#include "io/mesh_file.h"
#include "io/obj/number_format.h"
#include "io/obj/obj_error.h"
#include "io/obj_reader.h"
#include "mesh_state_difference.h"
#include "obj_test_support.h"
#include "rgb/lod/refine.h"
#include "rgb/lod/requests.h"
#include "rgb/mesh/invariants.h"
#include "rgb/values/loop_geometry.h"
#include "rgb/values/restore_state.h"
#include "support/oracle_limit.h"
#include "support/same_mesh.h"
#include "support/set_level.h"

namespace rgbio {
namespace {

rgb::Mesh octahedron() { return build_mesh(read_obj_text(test::kOctahedron, "octahedron.obj")); }

// A square grid patch with a boundary (n x n quads), so boundary rules are exercised too.
std::string grid_obj(int n) {
    std::string text;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) text += "v " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string((x * y) % 3 * 0.25) + "\n";
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const int a = y * (n + 1) + x + 1;
            text += "f " + std::to_string(a) + " " + std::to_string(a + 1) + " " + std::to_string(a + n + 2) + " " + std::to_string(a + n + 1) + "\n";
        }
    return text;
}

void set_level(rgb::Mesh& mesh, const glm::dvec3& centre, double radius, int level) {
    rgb::LevelRequest request;
    request.level = level;
    request.sphere = rgb::Sphere{centre, radius};
    rgb::apply_request(mesh, request);
}

// A deterministic sequence of refinements and coarsenings in spheres.
void edit(rgb::Mesh& mesh, int seed) {
    set_level(mesh, {0.9 * (seed % 3), 0.3, 0.5}, 0.7, 3 + seed % 2);
    set_level(mesh, {0.2, 0.8, 0.2 * seed}, 0.5, 1);
    set_level(mesh, {0.5, 0.5, 0.5}, 0.4, 4);
}

rgb::Mesh round_trip(const rgb::Mesh& mesh, const SaveOptions& options = {}) {
    const LoadedMesh loaded = read_obj_text(format_obj(mesh, options), "saved.obj");
    EXPECT_TRUE(loaded.adaptive) << "the state was dropped: " << (loaded.warnings.empty() ? "" : loaded.warnings.front());
    return build_mesh(loaded);
}

void expect_same_state(const rgb::MeshState& a, const rgb::MeshState& b) { EXPECT_EQ(test::state_difference(a, b), ""); }

TEST(MeshFile, PlainObjLoadsAsABaseMesh) {
    const rgb::Mesh mesh = octahedron();
    EXPECT_EQ(mesh.num_vertices(), 6u);
    EXPECT_EQ(mesh.num_faces(), 8u);
    for (rgb::FaceId f : mesh.faces()) {
        EXPECT_EQ(mesh.colour(f), rgb::Colour::Green);
        EXPECT_EQ(mesh.level(f), 0);
    }
    for (rgb::VertexId v : mesh.vertices()) EXPECT_EQ(mesh.level(v), 0);
    EXPECT_TRUE(rgb::check_invariants(mesh).ok());
}

TEST(MeshFile, StateTextIsLossless) {
    rgb::Mesh mesh = octahedron();
    edit(mesh, 1);
    const LoadedMesh loaded = read_obj_text(format_obj(mesh, {}), "saved.obj");
    ASSERT_TRUE(loaded.adaptive);
    expect_same_state(rgb::capture_state(*loaded.adaptive), rgb::capture_state(mesh));
}

TEST(MeshFile, SavedAdaptiveMeshRestoresBitForBit) {
    rgb::Mesh mesh = octahedron();
    edit(mesh, 1);
    ASSERT_GT(mesh.max_vertex_level(), 2);
    const rgb::Mesh restored = round_trip(mesh);
    EXPECT_TRUE(rgb::check_invariants(restored).ok());
    EXPECT_TRUE(rgbtest::same_mesh(restored, mesh));
    expect_same_state(rgb::capture_state(restored), rgb::capture_state(mesh));
}

TEST(MeshFile, MeshWithBoundaryRestoresBitForBit) {
    rgb::Mesh mesh = build_mesh(read_obj_text(grid_obj(4), "grid.obj"));
    edit(mesh, 1);
    const rgb::Mesh restored = round_trip(mesh);
    EXPECT_TRUE(rgbtest::same_mesh(restored, mesh));
    expect_same_state(rgb::capture_state(restored), rgb::capture_state(mesh));
}

// What restore_state says of a state: the reason it refuses it, or "restored".
std::string restore_problem(const rgb::MeshState& state) {
    try {
        rgb::restore_state(state);
    } catch (const std::invalid_argument& e) {
        return std::string(e.what());
    }
    return "restored";
}

// A grid of 64 x 64 squares at level 2: (4 * 64 + 1)^2 = 66,049 vertices and 131,072 faces, two
// parallel blocks of vertices (2^15 or more each) and of faces (2^16) at least.
rgb::MeshState large_grid_state() {
    rgb::Mesh mesh = build_mesh(read_obj_text(grid_obj(64), "grid.obj"));
    rgbtest::set_level(mesh, 2);
    return rgb::capture_state(mesh);
}

// restore_state finds each vertex's halfedge in parallel blocks of vertices: of two vertices that
// no face uses, the first in vertex order is named, whichever block it is in.
TEST(MeshFile, TheFirstVertexUsedByNoFaceIsNamed) {
    const rgb::MeshState state = large_grid_state();
    ASSERT_EQ(state.vertices.size(), 66049u);
    const std::uint32_t early = 16500, late = 49500;
    auto without_faces_of = [&](std::initializer_list<std::uint32_t> vertices) {
        rgb::MeshState cut = state;
        std::erase_if(cut.faces, [&](const rgb::Triangle& t) {
            return std::any_of(vertices.begin(), vertices.end(), [&](std::uint32_t v) { return std::find(t.begin(), t.end(), v) != t.end(); });
        });
        return cut;
    };
    EXPECT_EQ(restore_problem(without_faces_of({late})), "invalid RGB state: vertex 49500 is used by no face");
    EXPECT_EQ(restore_problem(without_faces_of({early, late})), "invalid RGB state: vertex 16500 is used by no face");
}

// The checks of addresses and faces run in parallel blocks too, and name what a plain loop would
// meet first: an invalid address before a later repeat (which is then not looked for), a repeat
// before a later invalid address; a face with a missing vertex before any that repeats a vertex,
// each the first in face order; a repeated directed edge at the later of the two faces using it.
TEST(MeshFile, TheFirstBadAddressOrFaceIsNamed) {
    const rgb::MeshState state = large_grid_state();
    ASSERT_EQ(state.faces.size(), 131072u);
    auto with = [&](const auto& change) {
        rgb::MeshState changed = state;
        change(changed);
        return restore_problem(changed);
    };
    const std::uint32_t nv = 66049;
    auto invalid = [](rgb::SurfacePoint& p) { p.level = 99; };
    EXPECT_EQ(with([&](rgb::MeshState& s) {
                  invalid(s.vertices[60000]);
                  invalid(s.vertices[20000]);
              }),
              "invalid RGB state: vertex 20000 has an invalid address");
    EXPECT_EQ(with([&](rgb::MeshState& s) {
                  invalid(s.vertices[50000]);
                  s.vertices[60000] = s.vertices[30000];
              }),
              "invalid RGB state: vertex 50000 has an invalid address");
    EXPECT_EQ(with([&](rgb::MeshState& s) {
                  invalid(s.vertices[50000]);
                  s.vertices[40000] = s.vertices[30000];
              }),
              "invalid RGB state: vertex 40000 repeats another vertex");
    EXPECT_EQ(with([&](rgb::MeshState& s) {
                  s.faces[10000][1] = s.faces[10000][0];
                  s.faces[100000][0] = nv;
                  s.faces[20000][2] = nv + 5;
              }),
              "invalid RGB state: face 20000 uses a missing vertex");
    EXPECT_EQ(with([&](rgb::MeshState& s) {
                  s.faces[90000][1] = s.faces[90000][0];
                  s.faces[30000][2] = s.faces[30000][1];
              }),
              "invalid RGB state: face 30000 repeats a vertex");
    EXPECT_EQ(with([&](rgb::MeshState& s) { s.faces[120000] = s.faces[40000]; }),
              "invalid RGB state: face 120000 repeats a directed edge (non-manifold)");
}

TEST(MeshFile, RefiningAfterLoadingMatchesRefiningWithoutSaving) {
    rgb::Mesh original = octahedron();
    edit(original, 0);
    rgb::Mesh restored = round_trip(original);
    for (int seed = 1; seed < 4; ++seed) {
        edit(original, seed);
        edit(restored, seed);
        EXPECT_TRUE(rgbtest::same_mesh(restored, original));
        restored = round_trip(restored);
    }
}

TEST(MeshFile, CoarseningAfterLoadingMatchesCoarseningWithoutSaving) {
    rgb::Mesh original = octahedron();
    for (int seed = 0; seed < 4; ++seed) edit(original, seed);
    rgb::Mesh restored = round_trip(original);
    rgb::apply_request(original, rgb::LevelRequest{});
    rgb::apply_request(restored, rgb::LevelRequest{});
    EXPECT_TRUE(rgbtest::same_mesh(restored, original));
    EXPECT_TRUE(rgbtest::same_mesh(restored, octahedron()));
}

// save_mesh streams the file a buffer at a time; it must hold exactly the text format_obj builds
// whole. Level 8 of the octahedron (524,288 triangles) with normals is several buffers long.
TEST(MeshFile, StreamedFileIsExactlyTheFormattedText) {
    rgb::Mesh mesh = octahedron();
    rgbtest::set_level(mesh, 8);
    rgbtest::set_level(mesh, 3, rgb::Sphere{{1, 0, 0}, 0.5});
    const SaveOptions options{.normals = true};
    const std::string expected = format_obj(mesh, options);
    ASSERT_GT(expected.size(), 3 * AtomicFileWriter::kBufferBytes);
    const std::filesystem::path path = std::filesystem::temp_directory_path() / ("rgbsub_streamed_" + std::to_string(::getpid()) + ".obj");
    save_mesh(mesh, path.string(), options);
    std::ifstream in(path, std::ios::binary);
    const std::string written((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::filesystem::remove(path);
    EXPECT_EQ(written.size(), expected.size());
    EXPECT_TRUE(written == expected) << "the streamed file differs from format_obj";
}

TEST(MeshFile, OtherReadersSeeTheDisplayedMesh) {
    rgb::Mesh mesh = octahedron();
    edit(mesh, 2);
    const std::string path = (std::filesystem::temp_directory_path() / "rgbsub_mesh_file_test.obj").string();
    save_mesh(mesh, path, {.normals = true});
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warnings, errors;
    ASSERT_TRUE(tinyobj::LoadObj(&attrib, &shapes, &materials, &warnings, &errors, path.c_str(), nullptr, false)) << errors;
    std::filesystem::remove(path);
    EXPECT_EQ(attrib.vertices.size(), 3 * mesh.num_vertices());
    EXPECT_EQ(attrib.normals.size(), 3 * mesh.num_vertices());
    ASSERT_EQ(shapes.size(), 1u);
    EXPECT_EQ(shapes[0].mesh.num_face_vertices.size(), mesh.num_faces());
    // The plain content read by our own loader: exact displayed positions, in live-slot order.
    const LoadedMesh plain = read_obj_text(format_obj(mesh, {.state = false}), "plain.obj");
    std::size_t i = 0;
    for (rgb::VertexId v : mesh.vertices()) EXPECT_EQ(plain.positions[i++], rgb::displayed_position(mesh, v));
}

TEST(MeshFile, LimitPositionsAreTheLoopLimitOfEveryVertex) {
    rgb::Mesh mesh = octahedron();
    set_level(mesh, {1, 0, 0}, 0.5, 2);
    const LoadedMesh plain = read_obj_text(format_obj(mesh, {.positions = SavedPositions::Limit, .state = false}), "limit.obj");
    // Independently of the core: Loop's limit mask applied to the uniform Loop oracle's mesh of the
    // vertex's level (test support has its own copy of the weights).
    const LoadedMesh input = read_obj_text(test::kOctahedron, "octahedron.obj");
    const rgbtest::UniformLoopOracle oracle(input.positions, input.triangles, 2);
    std::size_t i = 0;
    for (rgb::VertexId v : mesh.vertices()) {
        const glm::dvec3 want = rgbtest::oracle_limit(oracle, mesh, v);
        EXPECT_LT(glm::distance(plain.positions[i++], want), 1e-12) << "vertex " << v.idx;
    }
    // And the state keeps them, so the file restores.
    EXPECT_TRUE(rgbtest::same_mesh(round_trip(mesh, {.positions = SavedPositions::Limit}), mesh));
}

TEST(MeshFile, CorruptStateIsAnErrorNamingItsLine) {
    rgb::Mesh mesh = octahedron();
    edit(mesh, 0);
    std::string text = format_obj(mesh, {});
    const std::size_t at = text.find("#rgb a ");
    text.replace(at, 7, "#rgb a x");
    const std::size_t line = static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n')) + 1;
    const ObjError e = test::load_error(text);
    EXPECT_EQ(e.problem(), ObjProblem::BadState);
    EXPECT_EQ(e.line(), line);
    EXPECT_NE(e.reason().find("expected a number"), std::string::npos) << e.what();

    std::string truncated = format_obj(mesh, {});
    truncated.resize(truncated.find("#rgb end"));
    EXPECT_NE(test::load_error(truncated).reason().find("truncated"), std::string::npos);
}

TEST(MeshFile, ReorderedFacesStillRestore) {
    rgb::Mesh mesh = octahedron();
    edit(mesh, 0);
    std::string text = format_obj(mesh, {});
    // Another program re-saved the faces in a different order but kept the comments: the same mesh.
    // (These two faces are refined ones; untouched base faces the state takes from their f lines
    // must keep their place: state_format_test.)
    ASSERT_EQ(text.find("#rgb t-as-f 0 "), std::string::npos);
    ASSERT_EQ(text.find("#rgb t-as-f 1 "), std::string::npos);
    const std::size_t first_face = text.find("\nf ") + 1;
    const std::size_t second_face = text.find("\nf ", first_face) + 1;
    const std::size_t third_face = text.find("\nf ", second_face) + 1;
    const std::string a = text.substr(first_face, second_face - first_face), b = text.substr(second_face, third_face - second_face);
    text.replace(first_face, a.size() + b.size(), b + a);
    const LoadedMesh loaded = read_obj_text(text, "edited.obj");
    ASSERT_TRUE(loaded.adaptive);
    EXPECT_TRUE(rgbtest::same_mesh(*loaded.adaptive, mesh));
}

TEST(MeshFile, StateThatNoLongerFitsTheFacesIsDroppedWithAWarning) {
    rgb::Mesh mesh = octahedron();
    edit(mesh, 0);
    std::string text = format_obj(mesh, {});
    // Another program flipped one face: the state no longer describes the file.
    const std::size_t face = text.find("\nf ") + 3;
    const std::size_t end = text.find('\n', face);
    std::istringstream corners(text.substr(face, end - face));
    std::string x, y, z;
    corners >> x >> y >> z;
    text.replace(face, end - face, x + " " + z + " " + y);
    const LoadedMesh loaded = read_obj_text(text, "edited.obj");
    EXPECT_FALSE(loaded.adaptive);
    ASSERT_FALSE(loaded.warnings.empty());
    EXPECT_NE(loaded.warnings[0].find("does not match the file"), std::string::npos) << loaded.warnings[0];
}

TEST(MeshFile, PositionsEditedElsewhereWinOverTheState) {
    rgb::Mesh mesh = octahedron();
    edit(mesh, 1);
    // Another program scaled the mesh by 2 and kept the comments.
    const LoadedMesh original = read_obj_text(format_obj(mesh, {}), "saved.obj");
    std::string scaled;
    for (const glm::dvec3& p : original.positions) {
        scaled += "v";
        for (int i = 0; i < 3; ++i) append_double(scaled, 2.0 * p[i]);
        scaled += '\n';
    }
    const std::string text = format_obj(mesh, {});
    scaled += text.substr(text.find("\nf ") + 1);
    const LoadedMesh loaded = read_obj_text(scaled, "scaled.obj");
    EXPECT_FALSE(loaded.adaptive);
    ASSERT_FALSE(loaded.warnings.empty());
    EXPECT_NE(loaded.warnings[0].find("positions differ"), std::string::npos) << loaded.warnings[0];
    ASSERT_EQ(loaded.positions.size(), original.positions.size());
    for (std::size_t i = 0; i < loaded.positions.size(); ++i) EXPECT_EQ(loaded.positions[i], 2.0 * original.positions[i]);
}

// read_obj_file releases a saved file's text once its state is parsed; what comes after (warnings
// quoting the file, errors of the plain mesh when the state is dropped) must not need it.
TEST(MeshFile, ASavedFileReadFromDiskSaysWhatItsTextSays) {
    rgb::Mesh mesh = octahedron();
    edit(mesh, 1);
    const std::string saved = format_obj(mesh, {});
    const std::filesystem::path path = std::filesystem::temp_directory_path() / ("rgbsub_from_disk_" + std::to_string(::getpid()) + ".obj");
    auto write = [&](const std::string& text) { std::ofstream(path, std::ios::binary) << text; };
    // An unknown keyword after the state: the mesh restores, and the warning quotes the keyword.
    write(saved + "frobnicate 1\n");
    const LoadedMesh loaded = read_obj_file(path.string());
    ASSERT_TRUE(loaded.adaptive);
    EXPECT_TRUE(test::has_warning(loaded.warnings, "'frobnicate'")) << (loaded.warnings.empty() ? "" : loaded.warnings[0]);
    // A face line repeated (and the header's count raised to match): the state is dropped, and the
    // plain mesh's error is the one reading the same text from memory gives.
    const std::size_t face = saved.find("\nf ") + 1, end = saved.find('\n', face) + 1;
    std::string doubled = saved.substr(0, end) + saved.substr(face, end - face) + saved.substr(end);
    const std::string count = std::to_string(mesh.num_faces()) + " triangles";
    doubled.replace(doubled.find(count), count.size(), std::to_string(mesh.num_faces() + 1) + " triangles");
    write(doubled);
    const ObjError in_memory = test::load_error(doubled);
    EXPECT_EQ(in_memory.problem(), ObjProblem::DuplicateFace) << in_memory.what();
    try {
        read_obj_file(path.string());
        ADD_FAILURE() << "no error from the file";
    } catch (const ObjError& e) {
        EXPECT_EQ(e.problem(), in_memory.problem());
        EXPECT_EQ(e.line(), in_memory.line());
        EXPECT_EQ(e.reason(), in_memory.reason());
    }
    std::filesystem::remove(path);
}

TEST(MeshFile, OtherProgramsHashRgbCommentsAreIgnoredWithAWarning) {
    const LoadedMesh loaded = read_obj_text(std::string("#rgb hello\n") + test::kOctahedron, "foreign.obj");
    EXPECT_FALSE(loaded.adaptive);
    EXPECT_EQ(loaded.triangles.size(), 8u);
    ASSERT_FALSE(loaded.warnings.empty());
    EXPECT_NE(loaded.warnings[0].find("not an rgbsub state"), std::string::npos) << loaded.warnings[0];
}

TEST(MeshFile, StatesOfAnotherFormatVersionAreRefusedByName) {
    const std::string text = std::string(test::kOctahedron) + "#rgb state 1 6 8 6\n#rgb end\n";
    const ObjError e = test::load_error(text);
    EXPECT_EQ(e.problem(), ObjProblem::BadState);
    EXPECT_NE(e.reason().find("state format version 1"), std::string::npos) << e.what();
}

TEST(MeshFile, HugeValuesInTheStateAreRefusedLikeCoordinates) {
    rgb::Mesh mesh = octahedron();
    edit(mesh, 1);
    std::string text = format_obj(mesh, {});
    const std::size_t at = text.find("#rgb p ");
    text.replace(at, 7, "#rgb p 1e300 ");
    EXPECT_NE(test::load_error(text).reason().find("1e12"), std::string::npos);
}

}  // namespace
}  // namespace rgbio
