// Meshes of other formats (glTF, PLY, and STL/FBX through Assimp), written byte by byte here, read
// through the one entry point the CLI and the editor use (read_mesh_file): positions bit for bit as
// the file stores them (doubles where it stores doubles, floats where floats), vertices split per
// corner welded into one manifold with their texture coordinates kept per corner, node transforms
// composed, meshes as groups, materials, one warning naming what is dropped, and hostile files
// refused with an ObjError naming the file and the reason. `info` on them: foreign_info_test.cpp.
#include <cstdio>
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "foreign_fixtures.h"
#include "io/gltf/gltf_writer.h"
#include "io/mesh_reader.h"
#include "io/obj_reader.h"
#include "obj_test_support.h"
#include "scratch_folder.h"
#include "textured_grid.h"

namespace rgbio {
namespace {

using test::binary_tetrahedron_ply;
using test::GlbBuffer;
using test::has_warning;
using test::put;

// Per triangle, its corners as (x, y, z, u, v), rotated to start at the smallest (u, v = -1: none).
std::multiset<std::vector<std::array<double, 5>>> corners_of(const LoadedMesh& mesh) {
    std::multiset<std::vector<std::array<double, 5>>> out;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        std::vector<std::array<double, 5>> corners;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3& p = mesh.positions[mesh.triangles[t][k]];
            glm::dvec2 uv(-1.0);
            if (!mesh.triangle_texcoords.empty() && mesh.triangle_texcoords[t][k] != kNoIndex) uv = mesh.texcoords[mesh.triangle_texcoords[t][k]];
            corners.push_back({p.x, p.y, p.z, uv.x, uv.y});
        }
        std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
        out.insert(corners);
    }
    return out;
}

class ForeignFormats : public test::ScratchFolder {
protected:
    ObjError error_of(const std::string& name, const std::string& bytes) {
        write(name, bytes);
        try {
            read_mesh_file(path(name));
        } catch (const ObjError& e) {
            EXPECT_NE(std::string(e.what()).find(path(name)), std::string::npos) << e.what();
            return e;
        }
        ADD_FAILURE() << name << " was read";
        return ObjError(ObjProblem::Unreadable, "", 0, "none");
    }
};

// A square split along its diagonal, each triangle with its own three vertices (as a glTF exporter
// writes a UV seam): welded into four vertices, two triangles, each corner with its own UV.
TEST_F(ForeignFormats, GltfSeamVerticesAreWeldedAndUvsStayPerCorner) {
    const float a = 0.1f, b = 0.3f;
    GlbBuffer buffer;
    buffer.add_floats({0, 0, 0, a, 0, 0, a, b, 0, /**/ 0, 0, 0, a, b, 0, 0, b, 0}, "VEC3", 3);
    buffer.add_floats({0, 0, 1, 0, 1, 1, /**/ 0.5f, 0, 0.5f, 1, 0.25f, 0.75f}, "VEC2", 2);
    write("square.glb", buffer.file(R"("scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1}}]}])"));
    const LoadedMesh mesh = read_mesh_file(path("square.glb"));
    ASSERT_EQ(mesh.positions.size(), 4u);
    ASSERT_EQ(mesh.triangles.size(), 2u);
    const double x = a, y = b;  // the floats as stored, exactly
    // glTF's v runs down the image, OBJ's up: v becomes 1 - v (exact for these values).
    using C = std::array<double, 5>;
    std::multiset<std::vector<C>> expected = {{C{0, 0, 0, 0, 1}, C{x, 0, 0, 1, 1}, C{x, y, 0, 1, 0}},
                                              {C{0, 0, 0, 0.5, 1}, C{x, y, 0, 0.5, 0}, C{0, y, 0, 0.25, 0.25}}};
    EXPECT_EQ(corners_of(mesh), expected);
    EXPECT_TRUE(mesh.warnings.empty()) << mesh.warnings.front();
}

// OBJ -> glTF (rgbsub's writer, which splits the grid's vertices along its UV seam) -> rgbsub: the
// seam is welded back into the OBJ's 20 vertices and 24 triangles, and every corner keeps its
// position, colour and UV as the floats glTF stores (v as 1 - v both ways).
TEST_F(ForeignFormats, ObjThroughGltfKeepsPositionsAndFaceVaryingUvs) {
    const LoadedMesh obj = read_obj_text(test::textured_grid(true), "grid.obj");
    GltfMesh out{obj.positions, {}, obj.colours, obj.triangles, obj.texcoords, obj.triangle_texcoords, {}, {}};
    save_gltf(out, path("grid.glb"));
    const LoadedMesh back = read_mesh_file(path("grid.glb"));
    EXPECT_EQ(back.positions.size(), obj.positions.size());
    ASSERT_EQ(back.triangles.size(), obj.triangles.size());
    const auto f = [](double x) { return static_cast<double>(static_cast<float>(x)); };
    LoadedMesh expected = obj;
    for (glm::dvec3& p : expected.positions) p = {f(p.x), f(p.y), f(p.z)};
    for (glm::dvec2& uv : expected.texcoords) uv = {f(uv.x), 1.0 - f(1.0 - uv.y)};
    EXPECT_EQ(corners_of(back), corners_of(expected));
    // Colours by position.
    std::map<std::array<double, 3>, glm::dvec3> colour_at;
    for (std::size_t v = 0; v < expected.positions.size(); ++v)
        colour_at[{expected.positions[v].x, expected.positions[v].y, expected.positions[v].z}] =
            glm::dvec3(f(obj.colours[v].x), f(obj.colours[v].y), f(obj.colours[v].z));
    ASSERT_EQ(back.colours.size(), back.positions.size());
    for (std::size_t v = 0; v < back.positions.size(); ++v)
        EXPECT_EQ(back.colours[v], (colour_at[{back.positions[v].x, back.positions[v].y, back.positions[v].z}]));
}

// Node transforms compose along the hierarchy (translation of the parent after the child's scale;
// a matrix given whole), each placed mesh becomes a group, and the material keeps its base colour
// and its texture file.
TEST_F(ForeignFormats, GltfNodeTransformsGroupsAndMaterials) {
    GlbBuffer buffer;
    buffer.add_floats({1, 0, 0, 0, 1, 0, 0, 0, 1}, "VEC3", 3);
    write("placed.glb",
          buffer.file(R"("scene":0,"scenes":[{"nodes":[0,2]}],)"
                      R"("nodes":[{"name":"left","translation":[1,2,3],"children":[1]},{"scale":[2,2,2],"mesh":0},)"
                      R"({"name":"right","matrix":[1,0,0,0, 0,1,0,0, 0,0,1,0, -5,0.5,0,1],"mesh":0}],)"
                      R"("meshes":[{"name":"tri","primitives":[{"attributes":{"POSITION":0},"material":0}]}],)"
                      R"("materials":[{"name":"paint","pbrMetallicRoughness":{"baseColorFactor":[0.25,0.5,0.75,1],"baseColorTexture":{"index":0}}}],)"
                      R"("textures":[{"source":0}],"images":[{"uri":"paint.png"}])"));
    const LoadedMesh mesh = read_mesh_file(path("placed.glb"));
    ASSERT_EQ(mesh.triangles.size(), 2u);
    // left: 2 p + (1, 2, 3); right: p + (-5, 0.5, 0): exact in doubles.
    std::set<std::array<double, 3>> expected = {{3, 2, 3}, {1, 4, 3}, {1, 2, 5}, {-4, 0.5, 0}, {-5, 1.5, 0}, {-5, 0.5, 1}};
    std::set<std::array<double, 3>> got;
    for (const glm::dvec3& p : mesh.positions) got.insert({p.x, p.y, p.z});
    EXPECT_EQ(got, expected);
    EXPECT_EQ(mesh.face_groups.names, (std::vector<std::string>{"tri", "right"}));
    ASSERT_EQ(mesh.face_groups.of_triangle.size(), 2u);
    EXPECT_NE(mesh.face_groups.of_triangle[0], mesh.face_groups.of_triangle[1]);
    ASSERT_EQ(mesh.materials.size(), 1u);
    EXPECT_EQ(mesh.materials[0].name, "paint");
    EXPECT_EQ(mesh.materials[0].diffuse, glm::dvec3(0.25, 0.5, 0.75));
    EXPECT_EQ(mesh.materials[0].diffuse_texture, path("paint.png"));
    EXPECT_EQ(mesh.face_materials.names, std::vector<std::string>{"paint"});
    EXPECT_EQ(mesh.face_materials.of_triangle, (std::vector<std::uint32_t>{0, 0}));
}

// What cannot be kept is named in one warning.
TEST_F(ForeignFormats, GltfDroppedContentIsOneWarning) {
    GlbBuffer buffer;
    buffer.add_floats({1, 0, 0, 0, 1, 0, 0, 0, 1}, "VEC3", 3);
    buffer.add_floats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
    write("extra.glb", buffer.file(R"("scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],"cameras":[{"type":"perspective","perspective":{"yfov":1,"znear":0.1}}],)"
                                   R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"NORMAL":1}}]}])"));
    const LoadedMesh mesh = read_mesh_file(path("extra.glb"));
    ASSERT_EQ(mesh.warnings.size(), 1u);
    EXPECT_TRUE(has_warning(mesh.warnings, "1 cameras"));
    EXPECT_TRUE(has_warning(mesh.warnings, "normals"));
}

TEST_F(ForeignFormats, GltfIndexedStripAndExternalBuffer) {
    // A strip of four vertices is two triangles; a .gltf names its buffer as a file beside it.
    std::string bin;
    for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 1.f, 1.f, 0.f}) put<float>(bin, v);
    for (std::uint16_t i : {0, 1, 2, 3}) put<std::uint16_t>(bin, i);
    write("strip.bin", bin);
    write("strip.gltf", R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
                        R"("buffers":[{"uri":"strip.bin","byteLength":56}],)"
                        R"("bufferViews":[{"buffer":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":8}],)"
                        R"("accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"},{"bufferView":1,"componentType":5123,"count":4,"type":"SCALAR"}],)"
                        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"mode":5}]}]})");
    const LoadedMesh mesh = read_mesh_file(path("strip.gltf"));
    EXPECT_EQ(mesh.positions.size(), 4u);
    EXPECT_EQ(mesh.triangles.size(), 2u);
    EXPECT_TRUE(mesh.warnings.empty()) << mesh.warnings.front();  // consistently oriented as the spec's strip order
}

TEST_F(ForeignFormats, GltfHostileFiles) {
    GlbBuffer buffer;
    buffer.add_floats({1, 0, 0, 0, 1, 0, 0, 0, 1}, "VEC3", 3);
    const std::string good = buffer.file(R"("scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}])");
    for (std::size_t cut : {std::size_t(5), std::size_t(20), good.size() / 2, good.size() - 4})
        EXPECT_EQ(error_of("cut.glb", good.substr(0, cut)).problem(), ObjProblem::Malformed) << cut;
    EXPECT_EQ(error_of("bad.gltf", "{ not json").problem(), ObjProblem::Malformed);
    // An accessor that reaches past its view.
    std::string json = buffer.json(R"("scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}])");
    json.replace(json.find(R"("count":3)"), 9, R"("count":300)");
    const ObjError past = error_of("past.glb", test::glb_file(json, buffer.bytes));
    EXPECT_EQ(past.problem(), ObjProblem::Malformed);
    EXPECT_NE(past.reason().find("bad accessor"), std::string::npos) << past.reason();
    // An index beyond the vertices.
    GlbBuffer indexed = buffer;
    indexed.add_indices({0, 1, 9});
    EXPECT_EQ(error_of("index.glb", indexed.file(R"("scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}])"))
                  .problem(),
              ObjProblem::Malformed);
    // Points only: no triangles.
    EXPECT_EQ(error_of("points.glb", buffer.file(R"("scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},"mode":0}]}])"))
                  .problem(),
              ObjProblem::NoFaces);
    // A node that is its own child.
    EXPECT_EQ(error_of("cycle.glb", buffer.file(R"("scenes":[{"nodes":[0]}],"nodes":[{"mesh":0,"children":[0]}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}])"))
                  .problem(),
              ObjProblem::Malformed);
}

// PLY positions exactly as stored: ASCII numbers correctly rounded to doubles, a quad triangulated,
// per-corner texture coordinates (texcoord lists) kept.
TEST_F(ForeignFormats, AsciiPlyDoublesBitForBit) {
    const std::vector<glm::dvec3> p = {{0.1, 1.0 / 3.0, -0.0}, {2.0 / 3.0, 1e-7, 0.2}, {0.7, 0.9, 1.0 / 7.0}, {-0.3, 0.8, 0.0}, {1.5, 0.4, 3.0 / 11.0}};
    std::string text = "ply\nformat ascii 1.0\ncomment written by hand\nelement vertex 5\nproperty double x\nproperty double y\nproperty double z\n"
                       "element face 2\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\nend_header\n";
    char line[200];
    for (const glm::dvec3& v : p) {
        std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", v.x, v.y, v.z);
        text += line;
    }
    text += "4 0 1 2 3 8 0 0 1 0 1 1 0 1\n3 1 4 2 6 0.5 0.5 0.75 0.5 0.5 0.75\n";
    write("exact.ply", text);
    const LoadedMesh mesh = read_mesh_file(path("exact.ply"));
    ASSERT_EQ(mesh.positions.size(), 5u);
    EXPECT_EQ(mesh.triangles.size(), 3u);
    for (const glm::dvec3& v : p) EXPECT_NE(std::find(mesh.positions.begin(), mesh.positions.end(), v), mesh.positions.end()) << v.x;
    // The triangle's corners carry its own UVs; vertex 1 and 2 also carry the quad's.
    using C = std::array<double, 5>;
    const auto corners = corners_of(mesh);
    std::vector<C> triangle = {C{p[1].x, p[1].y, p[1].z, 0.5, 0.5}, C{p[4].x, p[4].y, p[4].z, 0.75, 0.5}, C{p[2].x, p[2].y, p[2].z, 0.5, 0.75}};
    std::rotate(triangle.begin(), std::min_element(triangle.begin(), triangle.end()), triangle.end());
    EXPECT_EQ(corners.count(triangle), 1u);
    EXPECT_TRUE(mesh.warnings.front().find("triangulated 1 quads") != std::string::npos) << mesh.warnings.front();
}

// Normals are named once in the dropped warning, as recomputed: positions move under subdivision, so
// every written normal is the subdivided surface's own (docs/files.md).
TEST_F(ForeignFormats, NormalsAreNamedOnceAsRecomputed) {
    const auto entries_naming_normals = [](const std::string& warning) {
        std::size_t n = 0;
        for (std::size_t at = 0, end = 0; at < warning.size(); at = end + 2) {
            end = std::min(warning.find("; ", at), warning.size());
            n += warning.substr(at, end - at).find("normals") != std::string::npos;
        }
        return n;
    };
    write("normals.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                         "property float nx\nproperty float ny\nproperty float nz\nproperty float quality\n"
                         "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                         "0 0 0 0 0 1 5\n1 0 0 0 0 1 5\n0 1 0 0 0 1 5\n3 0 1 2\n");
    const LoadedMesh ply = read_mesh_file(path("normals.ply"));
    ASSERT_EQ(ply.warnings.size(), 1u);
    EXPECT_TRUE(has_warning(ply.warnings, "vertex normals (nx, ny, nz) (not kept: written normals are recomputed")) << ply.warnings[0];
    EXPECT_TRUE(has_warning(ply.warnings, "1 other vertex properties (alpha, quality, ...)")) << ply.warnings[0];
    EXPECT_EQ(entries_naming_normals(ply.warnings[0]), 1u) << ply.warnings[0];

    GlbBuffer buffer;
    buffer.add_floats({1, 0, 0, 0, 1, 0, 0, 0, 1}, "VEC3", 3);
    buffer.add_floats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
    write("normals.glb", buffer.file(R"("scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0,"NORMAL":1}}]}])"));
    const LoadedMesh gltf = read_mesh_file(path("normals.glb"));
    ASSERT_EQ(gltf.warnings.size(), 1u);
    EXPECT_TRUE(has_warning(gltf.warnings, "1 primitives' normals (not kept: written normals are recomputed")) << gltf.warnings[0];
    EXPECT_EQ(entries_naming_normals(gltf.warnings[0]), 1u) << gltf.warnings[0];
}

TEST_F(ForeignFormats, BinaryPlyPositionsAndColours) {
    const std::vector<glm::dvec3> p = {{0.1, 0.2, 0.3}, {1.0 / 3.0, 0.0, 0.0}, {0.0, 1.1, 0.0}, {0.0, 0.0, 2.0 / 3.0}};
    write("le.ply", binary_tetrahedron_ply(false, true, p));
    const LoadedMesh le = read_mesh_file(path("le.ply"));
    EXPECT_EQ(le.positions, p);  // every vertex used, in file order
    EXPECT_EQ(le.triangles.size(), 4u);
    ASSERT_EQ(le.colours.size(), 4u);
    EXPECT_EQ(le.colours[3], glm::dvec3(1.0, 128.0 / 255.0, 3.0 / 255.0));
    EXPECT_TRUE(has_warning(le.warnings, "1 elements 'edge'"));
    write("be.ply", binary_tetrahedron_ply(true, false, p));
    const LoadedMesh be = read_mesh_file(path("be.ply"));
    ASSERT_EQ(be.positions.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(be.positions[i][c], static_cast<double>(static_cast<float>(p[i][c])));
}

TEST_F(ForeignFormats, PlyHostileFiles) {
    const std::vector<glm::dvec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const std::string good = binary_tetrahedron_ply(false, true, p);
    const std::size_t body = good.find("end_header\n") + 11;
    for (std::size_t cut : {body - 3, body + 10, good.size() - 30, good.size() - 1})
        EXPECT_EQ(error_of("cut.ply", good.substr(0, cut)).problem(), ObjProblem::Malformed) << cut;
    std::string long_list = good;
    long_list[body + 4 * 27] = static_cast<char>(255);  // the first face's corner count
    EXPECT_EQ(error_of("list.ply", long_list).problem(), ObjProblem::Malformed);
    EXPECT_EQ(error_of("index.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                                    "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n")
                  .problem(),
              ObjProblem::Malformed);
    EXPECT_EQ(error_of("word.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 x 0\n")
                  .problem(),
              ObjProblem::Malformed);
    EXPECT_EQ(error_of("nofaces.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n")
                  .problem(),
              ObjProblem::NoFaces);
    EXPECT_EQ(error_of("nan.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                                  "element face 1\nproperty list uchar int vertex_indices\nend_header\nnan 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
                  .problem(),
              ObjProblem::NonFiniteCoordinate);
}

// STL stores a vertex per corner: welded, a tetrahedron is closed (Euler characteristic 2); a facet
// with coinciding corners and a repeated facet are dropped with a warning each.
TEST_F(ForeignFormats, StlCornersAreWelded) {
    const float a = 0.1f, b = 0.7f, c = 1.3f;
    std::vector<std::array<float, 9>> facets = {{0, 0, 0, 0, b, 0, a, 0, 0}, {0, 0, 0, a, 0, 0, 0, 0, c}, {a, 0, 0, 0, b, 0, 0, 0, c}, {0, b, 0, 0, 0, 0, 0, 0, c}};
    write("tetra.stl", test::binary_stl(facets));
    const LoadedMesh mesh = read_mesh_file(path("tetra.stl"));
    ASSERT_EQ(mesh.positions.size(), 4u);
    ASSERT_EQ(mesh.triangles.size(), 4u);
    std::set<std::array<double, 3>> got;
    for (const glm::dvec3& p : mesh.positions) got.insert({p.x, p.y, p.z});
    EXPECT_EQ(got, (std::set<std::array<double, 3>>{{0, 0, 0}, {a, 0, 0}, {0, b, 0}, {0, 0, c}}));
    facets.push_back({a, 0, 0, a, 0, 0, 0, 0, c});
    facets.push_back(facets[0]);
    write("extra.stl", test::binary_stl(facets));
    const LoadedMesh extra = read_mesh_file(path("extra.stl"));
    EXPECT_EQ(extra.triangles.size(), 4u);
    EXPECT_TRUE(has_warning(extra.warnings, "dropped 1 faces whose corners coincide"));
    EXPECT_TRUE(has_warning(extra.warnings, "dropped 1 faces over the same three vertices"));
}

TEST_F(ForeignFormats, AssimpErrorsNameTheFile) {
    const ObjError garbage = error_of("garbage.fbx", "this is not an FBX file at all\n");
    EXPECT_EQ(garbage.problem(), ObjProblem::Malformed);
    EXPECT_NE(garbage.reason().find("Assimp"), std::string::npos) << garbage.reason();
    EXPECT_EQ(error_of("cut.stl", test::binary_stl({{0, 0, 0, 1, 0, 0, 0, 1, 0}}).substr(0, 100)).problem(), ObjProblem::Malformed);
}

// The extension decides the reader in any case; other names stay OBJ.
TEST_F(ForeignFormats, ExtensionsInAnyCase) {
    write("UPPER.PLY", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                       "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    EXPECT_EQ(read_mesh_file(path("UPPER.PLY")).triangles.size(), 1u);
    write("mesh.txt", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_EQ(read_mesh_file(path("mesh.txt")).triangles.size(), 1u);
}

}  // namespace
}  // namespace rgbio
