// Materials, groups, objects and smoothing groups through refinement and saving: every face of a
// refined mesh carries the labels of the base face it lies in (found here by geometry, in base
// space), a saved file writes them back grouped (read with tinyobjloader, an independent reader),
// the state keeps the base faces' labels, and load -> refine -> save -> load -> level 0 gives back
// the input's labels.
#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include <gtest/gtest.h>
#include <tiny_obj_loader.h>

#include "io/base_attributes.h"
#include "io/mesh_file.h"
#include "io/obj/obj_error.h"
#include "io/obj_reader.h"
#include "obj_test_support.h"
#include "rgb/lod/requests.h"
#include "scratch_folder.h"
#include "support/same_mesh.h"
#include "support/set_level.h"

namespace rgbio {
namespace {

constexpr int kCells = 4;

// A flat kCells x kCells grid (z = 0), two triangles a cell, written cell by cell so that the labels
// change at nearly every face: material by the cell's column half, group by its row half, smoothing
// group 1 on a checkerboard (off elsewhere), object "grid" throughout.
std::string labelled_grid() {
    std::string text = "mtllib labels.mtl\no grid\n";
    for (int y = 0; y <= kCells; ++y)
        for (int x = 0; x <= kCells; ++x) text += "v " + std::to_string(x) + " " + std::to_string(y) + " 0\n";
    for (int y = 0; y < kCells; ++y)
        for (int x = 0; x < kCells; ++x) {
            const int a = y * (kCells + 1) + x + 1, b = a + 1, c = a + kCells + 2, d = a + kCells + 1;
            text += std::string("g ") + (y < kCells / 2 ? "bottom" : "top") + "\n";
            text += std::string("usemtl ") + (x < kCells / 2 ? "left" : "right") + "\n";
            text += std::string("s ") + ((x + y) % 2 == 0 ? "1" : "off") + "\n";
            text += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + "\n";
            text += "f " + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(d) + "\n";
        }
    return text;
}

const std::string kLabelsMtl = "newmtl left\nKd 1 0 0\nnewmtl right\nKd 0 0 1\n";

// The labels the grid gives the point (x, y) strictly inside a cell.
struct Expected {
    std::string material, group;
    int smoothing = 0;
};
Expected labels_at(const glm::dvec3& p) {
    const int x = static_cast<int>(p.x), y = static_cast<int>(p.y);
    return {x < kCells / 2 ? "left" : "right", y < kCells / 2 ? "bottom" : "top", (x + y) % 2 == 0 ? 1 : 0};
}

using Triple = std::array<std::uint32_t, 3>;
Triple sorted(Triple t) {
    std::sort(t.begin(), t.end());
    return t;
}

// Per face of the mesh (as sorted 0-based v-line indices of a save: live slots in order), the labels
// at the centroid of its corners' base-space positions. A face lies inside one base triangle, so its
// centroid is strictly inside one cell.
std::map<Triple, Expected> expected_by_geometry(const rgb::Mesh& mesh) {
    std::vector<std::uint32_t> line(mesh.vertex_capacity());
    std::uint32_t i = 0;
    for (rgb::VertexId v : mesh.vertices()) line[v.idx] = i++;
    std::map<Triple, Expected> expected;
    for (rgb::FaceId f : mesh.faces()) {
        glm::dvec3 centroid(0.0);
        Triple t;
        for (int c = 0; c < 3; ++c) {
            const rgb::VertexId v = mesh.face_vertices(f)[c];
            centroid += mesh.base_space_position(v) / 3.0;
            t[c] = line[v.idx];
        }
        expected[sorted(t)] = labels_at(centroid);
    }
    return expected;
}

class LabelledMesh : public test::ScratchFolder {
protected:
    LoadedAsset load_grid() {
        write("labels.mtl", kLabelsMtl);
        write("grid.obj", labelled_grid());
        return load_asset(path("grid.obj"));
    }
    std::size_t count_lines(const std::string& text, const std::string& start) {
        std::istringstream in(text);
        std::size_t n = 0;
        for (std::string line; std::getline(in, line);) n += line.rfind(start, 0) == 0;
        return n;
    }
};

TEST_F(LabelledMesh, RefinedFacesInheritTheirBaseFacesLabelsAndTheFileGroupsThem) {
    LoadedAsset asset = load_grid();
    rgbtest::set_level(asset.mesh, 3, rgb::Sphere{{1.2, 1.7, 0.0}, 1.1});
    rgbtest::set_level(asset.mesh, 1, rgb::Sphere{{3.5, 3.5, 0.0}, 0.8});
    ASSERT_GT(asset.mesh.num_faces(), 400u);
    SaveOptions options;
    options.attributes = asset.attributes;
    save_mesh(asset.mesh, path("refined.obj"), options);

    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warnings, errors;
    ASSERT_TRUE(tinyobj::LoadObj(&attrib, &shapes, &materials, &warnings, &errors, path("refined.obj").c_str(),
                                 folder_.c_str(), false))
        << errors;
    ASSERT_EQ(materials.size(), 2u);
    const std::map<Triple, Expected> expected = expected_by_geometry(asset.mesh);
    std::size_t faces = 0;
    for (const tinyobj::shape_t& shape : shapes)
        for (std::size_t f = 0; f < shape.mesh.material_ids.size(); ++f) {
            Triple t;
            for (int c = 0; c < 3; ++c) t[c] = static_cast<std::uint32_t>(shape.mesh.indices[3 * f + c].vertex_index);
            const auto it = expected.find(sorted(t));
            ASSERT_NE(it, expected.end());
            EXPECT_EQ(materials[shape.mesh.material_ids[f]].name, it->second.material);
            EXPECT_EQ(shape.name, it->second.group);
            EXPECT_EQ(shape.mesh.smoothing_group_ids[f], static_cast<unsigned>(it->second.smoothing));
            ++faces;
        }
    EXPECT_EQ(faces, asset.mesh.num_faces());

    // One block per label combination (2 materials x 2 groups x 2 smoothing values), not per face:
    // 2 g lines and 4 usemtl lines in the order the input first used them, 8 s lines.
    const std::string text = read(path("refined.obj"));
    EXPECT_EQ(count_lines(text, "g "), 2u);
    EXPECT_EQ(count_lines(text, "usemtl "), 4u);
    EXPECT_EQ(count_lines(text, "s "), 8u);
    EXPECT_EQ(count_lines(text, "mtllib labels.mtl"), 1u);
    EXPECT_EQ(count_lines(text, "o grid"), 1u);
    EXPECT_EQ(count_lines(text, "#rgb section face-labels 32"), 1u);
}

// Per triangle of a file: its corner positions (as a sorted key) and its labels by name.
std::map<std::vector<double>, std::array<std::string, 4>> labelled_triangles(const LoadedMesh& mesh) {
    std::map<std::vector<double>, std::array<std::string, 4>> out;
    auto name = [](const FaceLabels& l, std::size_t t) {
        return l.empty() || l.of_triangle[t] == kNoIndex ? std::string("-") : l.names[l.of_triangle[t]];
    };
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        std::vector<std::array<double, 3>> corners;
        for (std::uint32_t v : mesh.triangles[t]) corners.push_back({mesh.positions[v].x, mesh.positions[v].y, mesh.positions[v].z});
        std::sort(corners.begin(), corners.end());
        std::vector<double> key;
        for (const auto& c : corners) key.insert(key.end(), c.begin(), c.end());
        out[key] = {name(mesh.face_materials, t), name(mesh.face_groups, t), name(mesh.face_objects, t),
                    std::to_string(mesh.face_smoothing_groups.empty() ? 0 : mesh.face_smoothing_groups[t])};
    }
    return out;
}

TEST_F(LabelledMesh, RefineSaveLoadLevelZeroGivesBackTheInputLabels) {
    // A quad (triangulated), a bow-tie vertex (split: the documented repair), faces before any
    // usemtl, and all four kinds of label.
    const std::string input =
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 1 0\nv 2 2 0\nv 1 2 0\n"
        "f 1 2 3\n"
        "o part one\ng body trim\nusemtl skin\ns 2\nf 1 3 4\n"
        "o part two\nusemtl cloth\ns off\nf 3 5 6 7\n";
    write("in.obj", input);
    std::vector<std::string> warnings;
    LoadedAsset asset = load_asset(path("in.obj"), &warnings);
    EXPECT_TRUE(test::has_warning(warnings, "bow-tie") || test::has_warning(warnings, "fans")) << warnings.size();
    rgbtest::set_level(asset.mesh, 4, rgb::Sphere{{1.0, 1.0, 0.0}, 0.6});
    SaveOptions options;
    options.attributes = asset.attributes;
    save_mesh(asset.mesh, path("refined.obj"), options);

    LoadedAsset resumed = load_asset(path("refined.obj"));
    EXPECT_EQ(resumed.attributes->labels, asset.attributes->labels);
    rgbtest::set_level(resumed.mesh, 0);
    options.attributes = resumed.attributes;
    save_mesh(resumed.mesh, path("back.obj"), options);

    const LoadedMesh first = read_obj_file(path("in.obj"));
    const LoadedMesh back = read_obj_file(path("back.obj"));
    ASSERT_TRUE(back.adaptive);
    EXPECT_EQ(labelled_triangles(back), labelled_triangles(first));
    // Spot check against the text: the triangulated quad's two halves are cloth in "part two".
    std::size_t cloth = 0;
    for (const auto& [key, labels] : labelled_triangles(back)) cloth += labels[0] == "cloth" && labels[2] == "part two";
    EXPECT_EQ(cloth, 2u);
}

// The state takes untouched base faces from the f lines (t-as-f, state_format.h); grouped by label,
// those are not in slot order, and the records must name the lines they are on.
TEST_F(LabelledMesh, ALightlyRefinedMeshTakesItsBaseFacesFromTheGroupedFaceLines) {
    LoadedAsset asset = load_grid();
    rgbtest::set_level(asset.mesh, 1, rgb::Sphere{{0.5, 0.5, 0.0}, 0.3});
    SaveOptions options;
    options.attributes = asset.attributes;
    const std::string text = format_obj(asset.mesh, options);
    ASSERT_GT(count_lines(text, "#rgb t-as-f "), 1u) << "the grouping splits the base faces into several runs";
    const LoadedMesh loaded = read_obj_text(text, "grouped.obj");
    ASSERT_TRUE(loaded.adaptive) << (loaded.warnings.empty() ? "" : loaded.warnings.front());
    EXPECT_TRUE(rgbtest::same_mesh(*loaded.adaptive, asset.mesh));
    EXPECT_EQ(loaded.adaptive_labels, asset.attributes->labels);
}

// A state saved without labels, whose faces another program labelled alike within each base face:
// the state stays, and those labels become the base faces'. Labels that differ inside one base face
// cannot be the base faces': the file is loaded as a plain mesh.
TEST_F(LabelledMesh, LabelsAddedElsewhereToAStateWithoutThemBecomeTheBaseFacesLabels) {
    write("grid.obj", labelled_grid());
    rgb::Mesh mesh = load_mesh(path("grid.obj"));
    rgbtest::set_level(mesh, 1);
    std::istringstream saved(format_obj(mesh, {}));
    std::string alike, differing;
    std::size_t face = 0;
    for (std::string line; std::getline(saved, line);) {
        alike += line + "\n";
        // The first face "odd", every other "even": the first face's base face holds three more.
        if (line.rfind("f ", 0) == 0 && face++ < 2) differing += face == 1 ? "usemtl odd\n" : "usemtl even\n";
        differing += line + "\n";
    }
    alike.insert(alike.find("\nf ") + 1, "g everything\n");
    const LoadedMesh kept = read_obj_text(alike, "alike.obj");
    ASSERT_TRUE(kept.adaptive) << (kept.warnings.empty() ? "" : kept.warnings.front());
    EXPECT_EQ(kept.adaptive_labels.groups.names, std::vector<std::string>{"everything"});
    EXPECT_EQ(kept.adaptive_labels.groups.of_triangle, std::vector<std::uint32_t>(32, 0u));
    EXPECT_TRUE(kept.adaptive_labels.materials.empty());
    const LoadedMesh dropped = read_obj_text(differing, "differing.obj");
    EXPECT_FALSE(dropped.adaptive);
}

TEST_F(LabelledMesh, AMeshWithoutLabelsHasNoLabelLinesOrSection) {
    write("plain.obj", test::kOctahedron);
    LoadedAsset asset = load_asset(path("plain.obj"));
    rgbtest::set_level(asset.mesh, 2);
    SaveOptions options;
    options.attributes = asset.attributes;
    const std::string text = format_obj(asset.mesh, options);
    for (const char* keyword : {"usemtl", "mtllib", "\ng ", "\no ", "\ns ", "face-labels"}) EXPECT_EQ(text.find(keyword), std::string::npos) << keyword;
}

TEST_F(LabelledMesh, LabelsEditedInAnotherProgramWinOverTheState) {
    LoadedAsset asset = load_grid();
    rgbtest::set_level(asset.mesh, 1);
    SaveOptions options;
    options.attributes = asset.attributes;
    std::string text = format_obj(asset.mesh, options);
    text.replace(text.find("usemtl right"), 12, "usemtl green");
    const LoadedMesh edited = read_obj_text(text, "edited.obj");
    EXPECT_FALSE(edited.adaptive);
    EXPECT_TRUE(test::has_warning(edited.warnings, "has another material ('green') than its base face ('right')"))
        << (edited.warnings.empty() ? "" : edited.warnings.front());
    EXPECT_EQ(std::count(edited.face_materials.names.begin(), edited.face_materials.names.end(), "green"), 1);
}

TEST_F(LabelledMesh, MalformedLabelSectionsNameTheirLine) {
    LoadedAsset asset = load_grid();
    SaveOptions options;
    options.attributes = asset.attributes;
    const std::string text = format_obj(asset.mesh, options);
    auto error_for = [&](const std::string& from, const std::string& to) {
        std::string bad = text;
        bad.replace(bad.find(from), from.size(), to);
        try {
            read_obj_text(bad, "bad.obj");
        } catch (const ObjError& e) {
            EXPECT_EQ(e.problem(), ObjProblem::BadState) << e.what();
            return std::string(e.what());
        }
        ADD_FAILURE() << "no error for " << to;
        return std::string();
    };
    EXPECT_NE(error_for("#rgb section face-labels 32", "#rgb section face-labels 31").find("more face labels than the 31 announced"),
              std::string::npos);
    EXPECT_NE(error_for("#rgb section face-labels 32", "#rgb section face-labels 33").find("announces 33 faces, the base mesh has 32"),
              std::string::npos);
    EXPECT_NE(error_for("#rgb l 1 1 1 1", "#rgb l 7 1 1 1").find("names material 7 of 2"), std::string::npos);
    EXPECT_NE(error_for("#rgb l 1 1 1 1", "#rgb l 1 1 x 1").find("expected a label index, found 'x'"), std::string::npos);
    EXPECT_NE(error_for("#rgb l 1 1 1 1", "#rgb l 1 1 1 1 1").find("need four numbers"), std::string::npos);
    const std::string twice = error_for("#rgb end", "#rgb section face-labels 32\n#rgb end");
    EXPECT_NE(twice.find("appears twice"), std::string::npos) << twice;
}

TEST_F(LabelledMesh, MaterialLibrariesStillLeadToTheirFileFromAnotherFolder) {
    LoadedAsset asset = load_grid();
    std::filesystem::create_directories(folder_ / "out" / "deeper");
    SaveOptions options;
    options.attributes = asset.attributes;
    save_mesh(asset.mesh, path("out/deeper/moved.obj"), options);
    save_mesh(asset.mesh, path("same.obj"), options);
    EXPECT_NE(read(path("out/deeper/moved.obj")).find("\nmtllib ../../labels.mtl\n"), std::string::npos);
    EXPECT_NE(read(path("same.obj")).find("\nmtllib labels.mtl\n"), std::string::npos);
    const LoadedMesh moved = read_obj_file(path("out/deeper/moved.obj"));
    ASSERT_EQ(moved.materials.size(), 2u);
    EXPECT_EQ(moved.materials[1].diffuse, glm::dvec3(0, 0, 1));
    // Unrelated places: absolute. Absolute names stay as written.
    BaseAttributes elsewhere;
    elsewhere.material_libraries = {"sub/a.mtl", "/opt/b.mtl"};
    elsewhere.library_folder = "/usr/share/models";
    EXPECT_EQ(library_references(elsewhere, "/tmp/out"), (std::vector<std::string>{"/usr/share/models/sub/a.mtl", "/opt/b.mtl"}));
    EXPECT_EQ(library_references(elsewhere, "/usr/share/models/x"), (std::vector<std::string>{"../sub/a.mtl", "/opt/b.mtl"}));
}

}  // namespace
}  // namespace rgbio
