// Material libraries next to an OBJ file: names, diffuse colours and textures as the .mtl says,
// paths resolved against the right folder, and every missing piece a warning, never an error. Each
// library is read once, and what libraries may cost is capped: one beyond the cap is a warning.
#include <filesystem>

#include <gtest/gtest.h>

#include "io/materials/material_library.h"
#include "obj_test_support.h"
#include "scratch_folder.h"

namespace rgbio {
namespace {

namespace fs = std::filesystem;
using test::has_warning;

class MaterialLibrary : public test::ScratchFolder {
protected:
    void SetUp() override {
        ScratchFolder::SetUp();
        fs::create_directories(folder_ / "materials" / "textures");
    }
    static constexpr const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
};

TEST_F(MaterialLibrary, ReadsNamesColoursAndTexturesRelativeToTheirFiles) {
    // The library sits in a subfolder; its texture path is relative to it, written Windows-style.
    write("materials/paint.mtl",
          "newmtl Skin\nKd 0.25 0.5 0.75\nmap_Kd textures\\skin.png\n\nnewmtl  Plain \nKd 1 0 0\n");
    write("materials/textures/skin.png", "not really a png");
    write("model.obj", std::string("mtllib materials/paint.mtl\n") + kTriangle + "usemtl Skin\nf 1 2 3\n");
    const LoadedMesh mesh = read_obj_file(path("model.obj"));
    ASSERT_EQ(mesh.materials.size(), 2u);
    EXPECT_EQ(mesh.materials[0].name, "Skin");
    // tinyobjloader's number parser is not correctly rounded (0.75 comes back 1 ulp high).
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(mesh.materials[0].diffuse[i], 0.25 * (i + 1), 1e-15);
    EXPECT_EQ(mesh.materials[0].diffuse_texture, path("materials/textures/skin.png"));
    EXPECT_EQ(mesh.materials[0].library, path("materials/paint.mtl"));
    EXPECT_EQ(mesh.materials[1].name, "Plain");
    EXPECT_EQ(mesh.materials[1].diffuse, glm::dvec3(1, 0, 0));
    EXPECT_EQ(mesh.materials[1].diffuse_texture, "");
    EXPECT_TRUE(mesh.warnings.empty()) << mesh.warnings.front();
}

TEST_F(MaterialLibrary, MissingPiecesAreWarnings) {
    write("lib.mtl", "newmtl A\nKd 0 1 0\nmap_Kd gone.jpg\n");
    write("model.obj", std::string("mtllib lib.mtl missing.mtl\n") + kTriangle + "usemtl B\nf 1 2 3\n");
    const LoadedMesh mesh = read_obj_file(path("model.obj"));
    ASSERT_EQ(mesh.materials.size(), 1u);
    EXPECT_EQ(mesh.triangles.size(), 1u);
    EXPECT_TRUE(has_warning(mesh.warnings, "material library '" + path("missing.mtl") +
                                               "' was not read (cannot read the file: No such file or directory)"));
    EXPECT_TRUE(has_warning(mesh.warnings, "1 diffuse textures (map_Kd) are not there, the first '" + path("gone.jpg") + "' of material 'A'"));
    // B is undefined, but a library was not read, which says enough.
    EXPECT_FALSE(has_warning(mesh.warnings, "defined in no material library"));

    write("model2.obj", std::string("mtllib lib.mtl\n") + kTriangle + "usemtl B\nf 1 2 3\n");
    EXPECT_TRUE(has_warning(read_obj_file(path("model2.obj")).warnings,
                            "1 materials used by faces are defined in no material library (the first 'B')"));
}

// A name defined twice in one library and again in another is one material, its first definition,
// with a warning (issue 30, low items); before, info counted 4 materials "defined" beside a warning
// about the 2 names used.
TEST_F(MaterialLibrary, ANameDefinedAgainKeepsItsFirstDefinition) {
    write("twice.mtl", "newmtl A\nKd 1 0 0\nnewmtl A\nKd 0 1 0\n");
    write("other.mtl", "newmtl A\nKd 0 0 1\nnewmtl B\nKd 1 1 0\n");
    write("model.obj", std::string("mtllib twice.mtl other.mtl\n") + kTriangle + "usemtl A\nf 1 2 3\n");
    const LoadedMesh mesh = read_obj_file(path("model.obj"));
    ASSERT_EQ(mesh.materials.size(), 2u);
    EXPECT_EQ(mesh.materials[0].name, "A");
    EXPECT_EQ(mesh.materials[0].diffuse, glm::dvec3(1, 0, 0));
    EXPECT_EQ(mesh.materials[1].name, "B");
    ASSERT_EQ(mesh.warnings.size(), 1u);
    EXPECT_EQ(mesh.warnings[0], "2 material definitions repeat a name defined before, the first 'A' in '" + path("twice.mtl") +
                                    "'; each name keeps its first definition");
}

TEST_F(MaterialLibrary, ALibraryThatIsNotAFileIsNotRead) {
    fs::create_directories(folder_ / "dir.mtl");
    write("model.obj", std::string("mtllib dir.mtl\n") + kTriangle + "f 1 2 3\n");
    const LoadedMesh mesh = read_obj_file(path("model.obj"));
    EXPECT_TRUE(has_warning(mesh.warnings, "was not read (cannot read the file: it is a directory)"));
}

// A small OBJ naming one library thousands of times (in several spellings) reads it once.
TEST_F(MaterialLibrary, ALibraryNamedManyTimesIsReadOnce) {
    write("materials/paint.mtl", "newmtl Skin\nKd 0.25 0.5 0.75\nnewmtl Plain\nKd 1 0 0\n");
    std::string obj;
    for (int i = 0; i < 3000; ++i) obj += i % 2 ? "mtllib materials/paint.mtl\n" : "mtllib ./materials/../materials/paint.mtl\n";
    write("model.obj", obj + kTriangle + "usemtl Skin\nf 1 2 3\n");
    const LoadedMesh mesh = read_obj_file(path("model.obj"));
    ASSERT_EQ(mesh.materials.size(), 2u);
    EXPECT_EQ(mesh.materials[0].name, "Skin");
    EXPECT_EQ(mesh.materials[1].name, "Plain");
    EXPECT_TRUE(mesh.warnings.empty()) << mesh.warnings.front();
}

// A library larger than the libraries of a mesh may take together (made sparse: no disk space, and
// removed with the folder) is not read: a warning naming it, and the mesh loads.
TEST_F(MaterialLibrary, AnOversizedLibraryIsAWarning) {
    write("small.mtl", "newmtl Skin\nKd 0.25 0.5 0.75\n");
    write("huge.mtl", "newmtl Huge\nKd 1 0 0\n");
    fs::resize_file(folder_ / "huge.mtl", kMaxMaterialLibraryBytes + 1);
    write("model.obj", std::string("mtllib small.mtl huge.mtl\n") + kTriangle + "usemtl Skin\nf 1 2 3\n");
    const LoadedMesh mesh = read_obj_file(path("model.obj"));
    EXPECT_EQ(mesh.triangles.size(), 1u);
    ASSERT_EQ(mesh.materials.size(), 1u);
    EXPECT_EQ(mesh.materials[0].name, "Skin");
    EXPECT_TRUE(has_warning(mesh.warnings, "material library '" + path("huge.mtl") + "' was not read (it is " +
                                               std::to_string(kMaxMaterialLibraryBytes + 1) + " bytes, beyond the 16 MiB"))
        << mesh.warnings.front();
}

// Libraries that define more materials together than a mesh may read: the one that passes the
// cap is not read, with a warning naming it; the ones before it are.
TEST_F(MaterialLibrary, LibrariesDefiningTooManyMaterialsAreWarnings) {
    std::string many;
    for (std::size_t i = 0; i < kMaxLibraryMaterials; ++i) many += "newmtl m" + std::to_string(i) + "\n";
    write("many.mtl", many);
    write("one.mtl", "newmtl Skin\nKd 0.25 0.5 0.75\n");
    write("model.obj", std::string("mtllib many.mtl one.mtl\n") + kTriangle + "usemtl m0\nf 1 2 3\n");
    const LoadedMesh mesh = read_obj_file(path("model.obj"));
    EXPECT_EQ(mesh.materials.size(), kMaxLibraryMaterials);
    EXPECT_TRUE(has_warning(mesh.warnings, "material library '" + path("one.mtl") + "' was not read (it defines 1 material"))
        << mesh.warnings.front();
}

}  // namespace
}  // namespace rgbio
