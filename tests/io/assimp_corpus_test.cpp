// Every OBJ file of Debian's assimp-testmodels either loads with the counts an independent reader
// (tinyobjloader) derives from the file, or is rejected with the specific reason listed below.
// Loaded files also carry the texture coordinates and materials tinyobjloader reads, corner for
// corner, and bow-ties are split into exactly as many vertices as a fan count over tinyobjloader's
// faces gives.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include <gtest/gtest.h>
#include <tiny_obj_loader.h>

#include "io/obj/obj_error.h"
#include "io/obj_reader.h"
#include "obj_test_support.h"

namespace rgbio {
namespace {

const std::filesystem::path kCorpus = "/usr/share/assimp/models";

// The files rgbsub rejects, with why (checked by reading each file).
const std::map<std::string, ObjProblem> kRejected = {
    {"OBJ/box_UTF16BE.obj", ObjProblem::Utf16},                 // UTF-16 big endian with BOM
    {"OBJ/box_longline.obj", ObjProblem::DegenerateFace},       // a 168-gon cycling 1 2 3 4 1 2 3 4 ...
    {"OBJ/concave_polygon.obj", ObjProblem::DegenerateFace},    // its 66-gon passes vertex 31 twice
    {"OBJ/space_in_material_name.obj", ObjProblem::DegenerateFace},  // the same 66-gon
    {"OBJ/number_formats.obj", ObjProblem::Syntax},             // "3.1+e2" is not a number
    {"OBJ/point_cloud.obj", ObjProblem::NoFaces},               // vertices only
    {"OBJ/testline.obj", ObjProblem::NoFaces},                  // l elements only
    {"OBJ/testpoints.obj", ObjProblem::NoFaces},                // p elements only
    {"invalid/empty.obj", ObjProblem::Empty},                   // 0 bytes
    {"invalid/malformed.obj", ObjProblem::FaceIndexOutOfRange},  // f ... 12 with 8 vertices
    {"invalid/malformed2.obj", ObjProblem::Syntax},             // an empty f line
};

constexpr double kNoUv = -1e300;

struct Reference {
    bool ok = false;
    std::size_t faces = 0, triangles = 0, referenced_vertices = 0;
    bool repeated_vertex_in_a_face = false;
    std::size_t extra_fans = 0;  // sum over vertices of (fans of faces around it - 1)
    // For triangle faces, in file order: each corner's position and texture coordinate (kNoUv when
    // none); for every face, its material name ("" when it has none a library defines).
    std::vector<std::multiset<std::array<double, 5>>> corners;
    std::vector<std::string> materials;
    std::vector<std::size_t> face_triangles;  // per face: n - 2
};

// Counts, per vertex, the groups of its faces connected through edges at the vertex (a face list
// per vertex, joined by breadth-first search), the way a modeller would see the fans.
std::size_t count_extra_fans(const std::vector<std::vector<int>>& faces) {
    std::map<int, std::vector<std::size_t>> faces_at;
    for (std::size_t f = 0; f < faces.size(); ++f)
        for (int v : faces[f]) faces_at[v].push_back(f);
    auto neighbours_at = [&](std::size_t f, int v) {  // the two vertices next to v in face f
        const std::vector<int>& face = faces[f];
        const std::size_t k = std::find(face.begin(), face.end(), v) - face.begin();
        return std::set<int>{face[(k + 1) % face.size()], face[(k + face.size() - 1) % face.size()]};
    };
    std::size_t extra = 0;
    for (const auto& [v, around] : faces_at) {
        std::set<std::size_t> unvisited(around.begin(), around.end());
        std::size_t fans = 0;
        while (!unvisited.empty()) {
            ++fans;
            std::vector<std::size_t> queue{*unvisited.begin()};
            unvisited.erase(unvisited.begin());
            while (!queue.empty()) {
                const std::set<int> ends = neighbours_at(queue.back(), v);
                queue.pop_back();
                for (auto it = unvisited.begin(); it != unvisited.end();) {
                    const std::set<int> other = neighbours_at(*it, v);
                    if (std::any_of(ends.begin(), ends.end(), [&](int w) { return other.contains(w); })) {
                        queue.push_back(*it);
                        it = unvisited.erase(it);
                    } else {
                        ++it;
                    }
                }
            }
        }
        extra += fans - 1;
    }
    return extra;
}

// What tinyobjloader (without its triangulation) sees in the file.
Reference tinyobj_reference(const std::filesystem::path& file) {
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warnings, errors;
    Reference r;
    r.ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warnings, &errors, file.c_str(), file.parent_path().c_str(), false);
    std::set<int> used;
    std::vector<std::vector<int>> faces;
    for (const tinyobj::shape_t& shape : shapes) {
        std::size_t offset = 0;
        for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
            const unsigned n = shape.mesh.num_face_vertices[f];
            ++r.faces;
            r.triangles += n - 2u;
            std::set<int> in_face;
            std::multiset<std::array<double, 5>> corners;
            faces.emplace_back();
            for (std::size_t k = 0; k < n; ++k) {
                const tinyobj::index_t index = shape.mesh.indices[offset + k];
                const int v = index.vertex_index;
                used.insert(v);
                faces.back().push_back(v);
                r.repeated_vertex_in_a_face |= !in_face.insert(v).second;
                const double* p = &attrib.vertices[3 * v];
                const bool uv = index.texcoord_index >= 0;
                corners.insert({p[0], p[1], p[2], uv ? attrib.texcoords[2 * index.texcoord_index] : kNoUv,
                                uv ? attrib.texcoords[2 * index.texcoord_index + 1] : kNoUv});
            }
            if (n == 3) r.corners.push_back(corners);
            const int material = shape.mesh.material_ids[f];
            r.materials.push_back(material >= 0 ? materials[material].name : "");
            r.face_triangles.push_back(n - 2);
            offset += n;
        }
    }
    r.referenced_vertices = used.size();
    if (!r.repeated_vertex_in_a_face) r.extra_fans = count_extra_fans(faces);
    return r;
}

std::vector<std::filesystem::path> corpus_files() {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kCorpus))
        if (entry.is_regular_file() && entry.path().extension() == ".obj") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

// Triangle files keep their faces in file order (flips only swap corners): the corners of each
// triangle, as (position, texture coordinate) pairs, are those tinyobjloader reads.
void expect_same_corners(const LoadedMesh& mesh, const Reference& reference) {
    ASSERT_EQ(mesh.triangles.size(), reference.corners.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        std::vector<std::array<double, 5>> corners;
        for (int i = 0; i < 3; ++i) {
            const glm::dvec3& p = mesh.positions[mesh.triangles[t][i]];
            const std::uint32_t uv = mesh.triangle_texcoords.empty() ? kNoIndex : mesh.triangle_texcoords[t][i];
            corners.push_back({p.x, p.y, p.z, uv == kNoIndex ? kNoUv : mesh.texcoords[uv].x, uv == kNoIndex ? kNoUv : mesh.texcoords[uv].y});
        }
        std::sort(corners.begin(), corners.end());
        const std::vector<std::array<double, 5>> expected(reference.corners[t].begin(), reference.corners[t].end());
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 5; ++k)  // tinyobjloader's number parser is not correctly rounded
                ASSERT_NEAR(corners[i][k], expected[i][k], 1e-12 * std::max(1.0, std::abs(expected[i][k]))) << "triangle " << t;
    }
}

std::string trimmed(const std::string& s) {
    const std::size_t b = s.find_first_not_of(" \t\r");
    return b == std::string::npos ? "" : s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// Where tinyobjloader finds a face's material in a library, the face carries that name, and the
// material's diffuse colour is the library's.
void expect_same_materials(const LoadedMesh& mesh, const Reference& reference) {
    std::size_t triangle = 0;
    for (std::size_t f = 0; f < reference.faces; ++f) {
        const std::size_t count = reference.face_triangles[f];
        for (std::size_t k = 0; k < count; ++k, ++triangle) {
            if (reference.materials[f].empty()) continue;
            ASSERT_FALSE(mesh.face_materials.empty());
            const std::uint32_t id = mesh.face_materials.of_triangle[triangle];
            ASSERT_NE(id, kNoIndex);
            EXPECT_EQ(mesh.face_materials.names[id], trimmed(reference.materials[f])) << "triangle " << triangle;
        }
    }
}

TEST(AssimpCorpus, WusonLoadsWithItsBowTiesSplit) {
    const LoadedMesh mesh = read_obj_file((kCorpus / "OBJ/WusonOBJ.obj").string());
    EXPECT_TRUE(test::has_warning(mesh.warnings, "split 6 non-manifold vertices (bow-ties: fans of faces that touch only at the vertex) "
                                                 "into one vertex per fan (9 vertices added), the first is vertex 20 on line 22"));
    const LoadedMesh spider = read_obj_file((kCorpus / "OBJ/spider.obj").string(), {.strict = true});
    EXPECT_EQ(spider.triangles.size(), 1368u);  // strict reading still re-orients faces
    try {
        read_obj_file((kCorpus / "OBJ/WusonOBJ.obj").string(), {.strict = true});
        ADD_FAILURE() << "strict reading accepted the bow-ties";
    } catch (const ObjError& e) {
        EXPECT_EQ(e.problem(), ObjProblem::NonManifoldVertex) << e.what();
        EXPECT_EQ(e.line(), 22u) << e.what();
    }
}

TEST(AssimpCorpus, EveryFileLoadsWithTheReferenceCountsOrIsRejectedForItsReason) {
    ASSERT_TRUE(std::filesystem::is_directory(kCorpus)) << kCorpus << " is missing: install the Debian package assimp-testmodels";
    const std::vector<std::filesystem::path> files = corpus_files();
    EXPECT_GE(files.size(), 25u);
    std::size_t loaded_count = 0, textured = 0;
    for (const auto& file : files) {
        const std::string name = std::filesystem::relative(file, kCorpus).string();
        SCOPED_TRACE(name);
        const Reference reference = tinyobj_reference(file);
        const auto rejected = kRejected.find(name);
        if (rejected == kRejected.end()) {
            const LoadedMesh mesh = read_obj_file(file.string());
            EXPECT_EQ(mesh.triangles.size(), reference.triangles);
            // Each bow-tie fan beyond a vertex's first became a vertex of its own.
            EXPECT_EQ(mesh.positions.size(), reference.referenced_vertices + reference.extra_fans);
            if (reference.corners.size() == reference.faces) {
                expect_same_corners(mesh, reference);
                textured += !mesh.texcoords.empty();
            }
            expect_same_materials(mesh, reference);
            ++loaded_count;
            continue;
        }
        try {
            read_obj_file(file.string());
            ADD_FAILURE() << "loaded, but expected rejection: " << problem_name(rejected->second);
        } catch (const ObjError& e) {
            EXPECT_EQ(e.problem(), rejected->second) << e.what();
            EXPECT_EQ(std::string(e.what()).rfind(file.string(), 0), 0u) << "message must start with the path: " << e.what();
        }
        // Where the reference reader can confirm the reason, it must.
        const ObjProblem problem = rejected->second;
        if (problem == ObjProblem::NoFaces || problem == ObjProblem::Utf16 || problem == ObjProblem::Empty) {
            EXPECT_EQ(reference.faces, 0u);
        } else if (problem == ObjProblem::DegenerateFace) {
            EXPECT_TRUE(reference.repeated_vertex_in_a_face);
        } else if (problem == ObjProblem::FaceIndexOutOfRange) {
            EXPECT_FALSE(reference.ok);
        }
    }
    EXPECT_EQ(loaded_count + kRejected.size(), files.size()) << "a listed rejection names a file that is not installed";
    EXPECT_EQ(textured, 3u) << "spider, regr01 and WusonOBJ have texture coordinates on every corner";
}

}  // namespace
}  // namespace rgbio
