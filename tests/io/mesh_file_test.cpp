// Saving and loading rgb::Mesh: plain OBJ loads as a base mesh, saved files restore the adaptive
// state bit for bit, and further edits then give identical results to never having saved.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include <unistd.h>

#include <gtest/gtest.h>
#include <tiny_obj_loader.h>

#include "io/atomic_file.h"
#include "io/mesh_file.h"
#include "io/obj_error.h"
#include "io/obj_reader.h"
#include "mesh_state_compare.h"
#include "obj_test_support.h"
#include "rgb/invariants.h"
#include "rgb/loop_geometry.h"
#include "rgb/refine.h"

namespace rgbio {
namespace {

rgb::Mesh octahedron() { return build_mesh(read_obj_text(test::kOctahedron, "octahedron.obj"), "octahedron.obj"); }

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

// A deterministic sequence of refinements and coarsenings in spheres.
void edit(rgb::Mesh& mesh, int seed) {
    rgb::set_level(mesh, rgb::Region::sphere({0.9 * (seed % 3), 0.3, 0.5}, 0.7), 3 + seed % 2);
    rgb::set_level(mesh, rgb::Region::sphere({0.2, 0.8, 0.2 * seed}, 0.5), 1);
    rgb::set_level(mesh, rgb::Region::sphere({0.5, 0.5, 0.5}, 0.4), 4);
}

rgb::Mesh round_trip(const rgb::Mesh& mesh, const SaveOptions& options = {}) {
    return build_mesh(read_obj_text(format_obj(mesh, options), "saved.obj"), "saved.obj");
}

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
    const rgb::MeshState state = rgb::capture_state(mesh);
    const LoadedMesh loaded = read_obj_text(format_obj(mesh, {}), "saved.obj");
    ASSERT_TRUE(loaded.state);
    test::expect_identical(*loaded.state, state);
}

TEST(MeshFile, SavedAdaptiveMeshRestoresBitForBit) {
    rgb::Mesh mesh = octahedron();
    edit(mesh, 1);
    ASSERT_GT(mesh.max_vertex_level(), 2);
    const rgb::Mesh restored = round_trip(mesh);
    EXPECT_TRUE(rgb::check_invariants(restored).ok());
    test::expect_identical(rgb::capture_state(restored), rgb::capture_state(mesh));
}

TEST(MeshFile, MeshWithBoundaryRestoresBitForBit) {
    rgb::Mesh mesh = build_mesh(read_obj_text(grid_obj(4), "grid.obj"), "grid.obj");
    edit(mesh, 1);
    const rgb::Mesh restored = round_trip(mesh);
    test::expect_identical(rgb::capture_state(restored), rgb::capture_state(mesh));
}

TEST(MeshFile, RefiningAfterLoadingMatchesRefiningWithoutSaving) {
    rgb::Mesh original = octahedron();
    edit(original, 0);
    rgb::Mesh restored = round_trip(original);
    for (int seed = 1; seed < 4; ++seed) {
        edit(original, seed);
        edit(restored, seed);
        test::expect_identical(rgb::capture_state(restored), rgb::capture_state(original));
        restored = round_trip(restored);
    }
}

TEST(MeshFile, CoarseningAfterLoadingMatchesCoarseningWithoutSaving) {
    rgb::Mesh original = octahedron();
    for (int seed = 0; seed < 4; ++seed) edit(original, seed);
    rgb::Mesh restored = round_trip(original);
    rgb::set_level(original, rgb::Region::everywhere(), 0);
    rgb::set_level(restored, rgb::Region::everywhere(), 0);
    test::expect_identical(rgb::capture_state(restored), rgb::capture_state(original));
}

// save_mesh streams the file a buffer at a time; it must hold exactly the text format_obj builds
// whole. Level 7 of the octahedron (131,072 triangles) with normals is several buffers long.
TEST(MeshFile, StreamedFileIsExactlyTheFormattedText) {
    rgb::Mesh mesh = octahedron();
    rgb::set_level(mesh, rgb::Region::everywhere(), 7);
    rgb::set_level(mesh, rgb::Region::sphere({1, 0, 0}, 0.5), 3);
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

TEST(MeshFile, LimitPositionsWhereKnownAndTheRestCounted) {
    rgb::Mesh mesh = octahedron();
    rgb::set_level(mesh, rgb::Region::sphere({1, 0, 0}, 0.5), 2);
    SaveReport report;
    const LoadedMesh plain = read_obj_text(format_obj(mesh, {.positions = SavedPositions::Limit, .state = false}, &report), "limit.obj");
    std::size_t i = 0, fallbacks = 0;
    for (rgb::VertexId v : mesh.vertices()) {
        const std::optional<glm::dvec3> limit = rgb::try_limit_position(mesh, v);
        if (!limit) ++fallbacks;
        EXPECT_EQ(plain.positions[i++], limit ? *limit : rgb::displayed_position(mesh, v));
    }
    EXPECT_EQ(report.limit_fallbacks, fallbacks);
}

TEST(MeshFile, CorruptStateIsAnErrorNamingItsLine) {
    rgb::Mesh mesh = octahedron();
    edit(mesh, 0);
    std::string text = format_obj(mesh, {});
    const std::size_t at = text.find("#rgb f 1 ");
    text.replace(at, 9, "#rgb f 1 x");
    const std::size_t line = static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n')) + 1;
    const ObjError e = test::load_error(text);
    EXPECT_EQ(e.problem(), ObjProblem::BadState);
    EXPECT_EQ(e.line(), line);
    EXPECT_NE(e.reason().find("expected a number"), std::string::npos) << e.what();

    std::string truncated = format_obj(mesh, {});
    truncated.resize(truncated.find("#rgb end"));
    EXPECT_NE(test::load_error(truncated).reason().find("truncated"), std::string::npos);
}

TEST(MeshFile, StateThatNoLongerMatchesTheFacesIsDroppedWithAWarning) {
    rgb::Mesh mesh = octahedron();
    edit(mesh, 0);
    std::string text = format_obj(mesh, {});
    // Another program re-saved the faces in a different order but kept the comments.
    const std::size_t first_face = text.find("\nf ") + 1;
    const std::size_t second_face = text.find("\nf ", first_face) + 1;
    const std::size_t third_face = text.find("\nf ", second_face) + 1;
    const std::string a = text.substr(first_face, second_face - first_face), b = text.substr(second_face, third_face - second_face);
    text.replace(first_face, a.size() + b.size(), b + a);
    const LoadedMesh loaded = read_obj_text(text, "edited.obj");
    EXPECT_FALSE(loaded.state);
    ASSERT_FALSE(loaded.warnings.empty());
    EXPECT_NE(loaded.warnings[0].find("does not match the faces"), std::string::npos);
    EXPECT_EQ(build_mesh(loaded, "edited.obj").num_faces(), mesh.num_faces());
}

}  // namespace
}  // namespace rgbio
