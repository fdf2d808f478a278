// Every OBJ file of Debian's assimp-testmodels either loads with the counts an independent reader
// (tinyobjloader) derives from the file, or is rejected with the specific reason listed below.
#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include <gtest/gtest.h>
#include <tiny_obj_loader.h>

#include "io/obj_error.h"
#include "io/obj_reader.h"

namespace rgbio {
namespace {

const std::filesystem::path kCorpus = "/usr/share/assimp/models";

// The files rgbsub rejects, with why (checked by reading each file).
const std::map<std::string, ObjProblem> kRejected = {
    {"OBJ/WusonOBJ.obj", ObjProblem::NonManifoldVertex},        // vertex 20: two fans of faces meet only there
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

struct Reference {
    bool ok = false;
    std::size_t faces = 0, triangles = 0, referenced_vertices = 0;
    bool repeated_vertex_in_a_face = false;
};

// What tinyobjloader (without its triangulation) sees in the file.
Reference tinyobj_reference(const std::filesystem::path& file) {
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warnings, errors;
    Reference r;
    r.ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warnings, &errors, file.c_str(), file.parent_path().c_str(), false);
    std::set<int> used;
    for (const tinyobj::shape_t& shape : shapes) {
        std::size_t offset = 0;
        for (unsigned char n : shape.mesh.num_face_vertices) {
            ++r.faces;
            r.triangles += n - 2u;
            std::set<int> in_face;
            for (std::size_t k = 0; k < n; ++k) {
                const int v = shape.mesh.indices[offset + k].vertex_index;
                used.insert(v);
                r.repeated_vertex_in_a_face |= !in_face.insert(v).second;
            }
            offset += n;
        }
    }
    r.referenced_vertices = used.size();
    return r;
}

std::vector<std::filesystem::path> corpus_files() {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kCorpus))
        if (entry.is_regular_file() && entry.path().extension() == ".obj") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

TEST(AssimpCorpus, EveryFileLoadsWithTheReferenceCountsOrIsRejectedForItsReason) {
    ASSERT_TRUE(std::filesystem::is_directory(kCorpus)) << kCorpus << " is missing: install the Debian package assimp-testmodels";
    const std::vector<std::filesystem::path> files = corpus_files();
    EXPECT_GE(files.size(), 25u);
    std::size_t loaded_count = 0;
    for (const auto& file : files) {
        const std::string name = std::filesystem::relative(file, kCorpus).string();
        SCOPED_TRACE(name);
        const Reference reference = tinyobj_reference(file);
        const auto rejected = kRejected.find(name);
        if (rejected == kRejected.end()) {
            const LoadedMesh mesh = read_obj_file(file.string());
            EXPECT_EQ(mesh.triangles.size(), reference.triangles);
            EXPECT_EQ(mesh.positions.size(), reference.referenced_vertices);
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
}

}  // namespace
}  // namespace rgbio
