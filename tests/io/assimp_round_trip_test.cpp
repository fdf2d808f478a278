// Every OBJ file of Debian's assimp-testmodels that loads goes through load -> refine (level 2) ->
// save -> load -> level 0 -> save -> load and comes back with the input's triangles (after the
// loader's documented repairs, which the state keeps), positions bit for bit, and each triangle's
// material, group, object and smoothing group, and mtllib lines that lead to the input's materials.
// The refined save leaves texture coordinates and colours out and says so; a save at level 0 keeps
// them, corner for corner.
#include <filesystem>
#include <map>

#include <gtest/gtest.h>

#include "io/base_attributes.h"
#include "io/mesh_file.h"
#include "io/obj/obj_error.h"
#include "io/obj_reader.h"
#include "rgb/lod/requests.h"
#include "support/set_level.h"

namespace rgbio {
namespace {

namespace fs = std::filesystem;

const fs::path kCorpus = "/usr/share/assimp/models/OBJ";

// Per triangle, by its corners' positions (a save may rotate a triangle: the key is the smallest of
// its three rotations, which also settles corners that coincide): its labels by name and its
// corners' texture coordinates and colours, in the same rotation.
using Key = std::vector<double>;
std::map<Key, std::vector<std::string>> described_triangles(const LoadedMesh& mesh, bool with_base_data) {
    std::map<Key, std::vector<std::string>> out;
    auto name = [](const FaceLabels& l, std::size_t t) {
        return l.empty() || l.of_triangle[t] == kNoIndex ? std::string("-") : l.names[l.of_triangle[t]];
    };
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const rgb::Triangle& tri = mesh.triangles[t];
        auto rotation = [&](int first) {
            Key key;
            for (int k = 0; k < 3; ++k) {
                const glm::dvec3& p = mesh.positions[tri[(first + k) % 3]];
                key.insert(key.end(), {p.x, p.y, p.z});
            }
            return key;
        };
        int first = 0;
        for (int c = 1; c < 3; ++c)
            if (rotation(c) < rotation(first)) first = c;
        Key key;
        std::vector<std::string> data{name(mesh.face_materials, t), name(mesh.face_groups, t), name(mesh.face_objects, t),
                                      std::to_string(mesh.face_smoothing_groups.empty() ? 0 : mesh.face_smoothing_groups[t])};
        for (int k = 0; k < 3; ++k) {
            const int c = (first + k) % 3;
            const glm::dvec3& p = mesh.positions[tri[c]];
            key.insert(key.end(), {p.x, p.y, p.z});
            if (!with_base_data) continue;
            const std::uint32_t uv = mesh.triangle_texcoords.empty() ? kNoIndex : mesh.triangle_texcoords[t][c];
            data.push_back(uv == kNoIndex ? "-" : std::to_string(mesh.texcoords[uv].x) + "," + std::to_string(mesh.texcoords[uv].y));
            if (!mesh.colours.empty()) data.push_back(std::to_string(mesh.colours[tri[c]].x));
        }
        out[key] = data;
    }
    return out;
}

// What a file's mtllib lines lead to: each material the libraries define, and the library it is in.
std::vector<std::string> described_materials(const LoadedMesh& mesh) {
    std::vector<std::string> out;
    for (const Material& m : mesh.materials)
        out.push_back(m.name + " Kd " + std::to_string(m.diffuse.x) + " " + std::to_string(m.diffuse.y) + " " +
                      std::to_string(m.diffuse.z) + " map_Kd " + m.diffuse_texture + " from " + m.library);
    return out;
}

// The first few triangles that differ between two descriptions (empty when none), readable.
std::vector<std::string> differences(const std::map<Key, std::vector<std::string>>& got,
                                     const std::map<Key, std::vector<std::string>>& wanted) {
    std::vector<std::string> out;
    auto describe = [](const char* what, const Key& key, const std::vector<std::string>* data) {
        std::string text = std::string(what) + " (";
        for (double x : key) text += std::to_string(x) + " ";
        text += "):";
        if (data == nullptr) return text + " missing";
        for (const std::string& d : *data) text += " " + d;
        return text;
    };
    for (const auto& [key, data] : wanted) {
        const auto it = got.find(key);
        if (it == got.end()) out.push_back(describe("wanted", key, nullptr));
        else if (it->second != data) out.push_back(describe("got", key, &it->second) + " / " + describe("wanted", key, &data));
        if (out.size() == 5) return out;
    }
    for (const auto& [key, data] : got)
        if (!wanted.contains(key) && out.size() < 5) out.push_back(describe("extra", key, &data));
    return out;
}

TEST(AssimpRoundTrip, LoadedFilesComeBackWithTheirLabelsAtLevelZero) {
    ASSERT_TRUE(fs::is_directory(kCorpus)) << kCorpus << " is missing: install the Debian package assimp-testmodels";
    const fs::path out = fs::temp_directory_path() / ("rgbsub_assimp_round_trip_" + std::to_string(::getpid()));
    fs::create_directories(out);
    std::size_t round_trips = 0, with_materials = 0;
    for (const fs::directory_entry& entry : fs::directory_iterator(kCorpus)) {
        if (entry.path().extension() != ".obj") continue;
        SCOPED_TRACE(entry.path().filename().string());
        LoadedMesh input;
        try {
            input = read_obj_file(entry.path().string());
        } catch (const ObjError&) {
            continue;  // the rejected files: assimp_corpus_test checks why
        }
        LoadedAsset asset = load_asset(entry.path().string());
        SaveOptions options;
        options.attributes = asset.attributes;
        const std::string level0 = (out / "level0.obj").string(), refined = (out / "refined.obj").string(),
                          back = (out / "back.obj").string();
        save_mesh(asset.mesh, level0, options);
        const LoadedMesh at_level0 = read_obj_file(level0);
        EXPECT_EQ(differences(described_triangles(at_level0, true), described_triangles(input, true)), std::vector<std::string>{});
        // Saved in another folder, the mtllib lines still lead to the input's libraries.
        EXPECT_EQ(described_materials(at_level0), described_materials(input));

        rgbtest::set_level(asset.mesh, 2);
        // Colours are written at every level; level-0 UVs without the UV layout are not.
        EXPECT_EQ(dropped_attributes(asset.mesh, asset.attributes.get()).empty(), input.triangle_texcoords.empty());
        save_mesh(asset.mesh, refined, options);
        LoadedAsset resumed = load_asset(refined);
        ASSERT_EQ(resumed.mesh.num_faces(), asset.mesh.num_faces()) << "the state was not used";
        EXPECT_EQ(resumed.attributes->labels, asset.attributes->labels);
        rgbtest::set_level(resumed.mesh, 0);
        options.attributes = resumed.attributes;
        save_mesh(resumed.mesh, back, options);
        const LoadedMesh final = read_obj_file(back);
        ASSERT_TRUE(final.adaptive);
        EXPECT_EQ(final.triangles.size(), input.triangles.size());
        EXPECT_EQ(differences(described_triangles(final, false), described_triangles(input, false)), std::vector<std::string>{});
        EXPECT_EQ(described_materials(final), described_materials(input));
        ++round_trips;
        with_materials += !input.materials.empty();
    }
    fs::remove_all(out);
    EXPECT_EQ(round_trips, 14u);
    // Of the files that load, those whose mtllib names a library that exists: box_mat_with_spaces,
    // cube_usemtl, empty_mat, regr01, regr_3429812, spider (cube_mtllib_after_g's is missing).
    EXPECT_EQ(with_materials, 6u);
}

}  // namespace
}  // namespace rgbio
