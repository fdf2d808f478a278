// Texture coordinates and vertex colours through saves: a save at level 0 writes them back exactly
// (read with tinyobjloader, an independent reader) and a saved level-0 file resumes with them; a
// refined save writes colours by the position rules, and leaves level-0 UVs out (saying so) when it
// has no UV layout.
#include <algorithm>
#include <map>
#include <set>
#include <sstream>

#include <gtest/gtest.h>
#include <tiny_obj_loader.h>

#include "io/base_attributes.h"
#include "io/mesh_file.h"
#include "obj_test_support.h"
#include "rgb/lod/requests.h"
#include "scratch_folder.h"
#include "support/set_level.h"

namespace rgbio {
namespace {

// Two triangles of a square with per-corner UVs (a seam: vertex 1 has two) and vertex colours.
const std::string kTextured =
    "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 1 1 0 0 0 1\nv 0 1 0 0.5 0.25 0.125\n"
    "vt 0 0\nvt 0.5 0\nvt 0.5 0.5\nvt 0 0.5\nvt 0.75 0.75\n"
    "f 1/1 2/2 3/3\nf 1/5 3/3 4/4\n";

// Each corner of the file as (x, y, z, u, v, r, g, b), read with tinyobjloader.
std::multiset<std::array<double, 8>> corners_read_independently(const std::string& path) {
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warnings, errors;
    EXPECT_TRUE(tinyobj::LoadObj(&attrib, &shapes, &materials, &warnings, &errors, path.c_str(), nullptr, false)) << errors;
    std::multiset<std::array<double, 8>> corners;
    for (const tinyobj::shape_t& shape : shapes)
        for (const tinyobj::index_t& i : shape.mesh.indices) {
            std::array<double, 8> c{};
            for (int k = 0; k < 3; ++k) {
                c[k] = attrib.vertices[3 * i.vertex_index + k];
                c[5 + k] = attrib.colors[3 * i.vertex_index + k];
            }
            for (int k = 0; k < 2; ++k) c[3 + k] = i.texcoord_index < 0 ? -1.0 : attrib.texcoords[2 * i.texcoord_index + k];
            corners.insert(c);
        }
    return corners;
}

class TexturedMesh : public test::ScratchFolder {};

TEST_F(TexturedMesh, ALevelZeroSaveKeepsTextureCoordinatesAndColours) {
    write("in.obj", kTextured);
    LoadedAsset asset = load_asset(path("in.obj"));
    // Refined and back: the mesh is its base mesh again.
    rgbtest::set_level(asset.mesh, 2);
    rgbtest::set_level(asset.mesh, 0);
    EXPECT_TRUE(dropped_attributes(asset.mesh, asset.attributes.get()).empty());
    SaveOptions options;
    options.attributes = asset.attributes;
    save_mesh(asset.mesh, path("level0.obj"), options);
    EXPECT_EQ(corners_read_independently(path("level0.obj")), corners_read_independently(path("in.obj")));

    // The saved file resumes (its state) with the same base attributes.
    std::vector<std::string> warnings;
    const LoadedAsset resumed = load_asset(path("level0.obj"), &warnings);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    EXPECT_EQ(resumed.attributes->texcoords, asset.attributes->texcoords);
    EXPECT_EQ(resumed.attributes->triangle_texcoords, asset.attributes->triangle_texcoords);
    EXPECT_EQ(resumed.attributes->colours, asset.attributes->colours);
    EXPECT_EQ(resumed.attributes->colours[3], glm::dvec3(0.5, 0.25, 0.125));
}

TEST_F(TexturedMesh, ARefinedSaveWithoutTheUvLayoutLeavesTheUvsOutAndSaysWhy) {
    write("in.obj", kTextured);
    LoadedAsset asset = load_asset(path("in.obj"));
    rgbtest::set_level(asset.mesh, 1);
    const std::vector<std::string> dropped = dropped_attributes(asset.mesh, asset.attributes.get());
    ASSERT_EQ(dropped.size(), 1u);
    EXPECT_TRUE(test::has_warning(dropped, "the texture coordinates (vt) are not written: the mesh is refined"));
    EXPECT_TRUE(dropped_attributes(asset.mesh, asset.attributes.get(), true).empty()) << "with the exact UV channel";
    SaveOptions options;
    options.attributes = asset.attributes;
    const std::string text = format_obj(asset.mesh, options);
    EXPECT_EQ(text.find("\nvt "), std::string::npos);
}

// Vertex colours follow the position rules, so a mesh whose colours are its positions is saved, at
// every level and for both kinds of positions, with each v line's colour equal to its position.
TEST_F(TexturedMesh, ARefinedSaveWritesEachVertexsColourByThePositionRules) {
    write("in.obj", "v 0 0 0 0 0 0\nv 1 0 0 1 0 0\nv 1 1 0.5 1 1 0.5\nv 0 1 0.25 0 1 0.25\nv 0.5 0.5 1 0.5 0.5 1\n"
                    "f 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n");
    LoadedAsset asset = load_asset(path("in.obj"));
    rgb::LevelRequest request;
    request.level = 3;
    request.sphere = rgb::Sphere{{1.0, 1.0, 0.5}, 0.6};
    rgb::apply_request(asset.mesh, request);
    EXPECT_TRUE(dropped_attributes(asset.mesh, asset.attributes.get()).empty());
    for (const SavedPositions positions : {SavedPositions::Displayed, SavedPositions::Limit}) {
        SaveOptions options;
        options.attributes = asset.attributes;
        options.positions = positions;
        std::istringstream lines(format_obj(asset.mesh, options));
        std::size_t coloured = 0;
        for (std::string line; std::getline(lines, line);) {
            if (line.rfind("v ", 0) != 0) continue;
            std::istringstream words(line.substr(2));
            std::vector<std::string> numbers;
            for (std::string w; words >> w;) numbers.push_back(w);
            ASSERT_EQ(numbers.size(), 6u) << line;
            EXPECT_EQ(std::vector<std::string>(numbers.begin(), numbers.begin() + 3), std::vector<std::string>(numbers.begin() + 3, numbers.end()))
                << line;
            ++coloured;
        }
        EXPECT_EQ(coloured, asset.mesh.num_vertices());
    }
}

TEST_F(TexturedMesh, TextureCoordinatesOfARefinedFileWithoutABaseUvsSectionAreIgnoredWithAWarning) {
    write("in.obj", kTextured);
    LoadedAsset asset = load_asset(path("in.obj"));
    rgbtest::set_level(asset.mesh, 1);
    save_mesh(asset.mesh, path("refined.obj"));
    // Another program gave the refined faces texture coordinates, which have no base counterpart.
    std::string text = read(path("refined.obj"));
    const std::size_t f = text.find("\nf ") + 1, end = text.find('\n', f);
    std::istringstream corners(text.substr(f + 2, end - f - 2));
    std::string with_uv = "vt 0.5 0.5\nf";
    for (std::string v; corners >> v;) with_uv += " " + v + "/1";
    text.replace(f, end - f, with_uv);
    write("refined.obj", text);
    std::vector<std::string> warnings;
    const LoadedAsset resumed = load_asset(path("refined.obj"), &warnings);
    EXPECT_EQ(resumed.mesh.num_faces(), asset.mesh.num_faces());  // the state still fits the faces
    EXPECT_TRUE(resumed.attributes->triangle_texcoords.empty());
    EXPECT_TRUE(test::has_warning(warnings, "texture coordinates dropped: the file is a refined mesh whose rgbsub state has no "
                                            "base-uvs section"));
}

}  // namespace
}  // namespace rgbio
