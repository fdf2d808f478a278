// The parts of the glTF writer that do not need a reader: naming materials by index, and saving
// like every other save (gltf_export_check.py reads the files themselves back).
#include <gtest/gtest.h>

#include "io/gltf/gltf_writer.h"
#include "io/obj/obj_error.h"

namespace rgbio {
namespace {

TEST(GltfWriter, MaterialIndicesFollowTheFaceMaterialNames) {
    FaceLabels labels;
    labels.names = {"wood", "undefined", "metal"};
    labels.of_triangle = {2, kNoIndex, 0, 1, 2};
    const std::vector<Material> materials = {{.name = "metal"}, {.name = "wood"}, {.name = "wood"}};
    EXPECT_EQ(material_indices(labels, materials), (std::vector<std::uint32_t>{0, kNoIndex, 1, kNoIndex, 0}));
    EXPECT_TRUE(material_indices({}, materials).empty());
}

TEST(GltfWriter, AFailedSaveIsASaveError) {
    GltfMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}};
    EXPECT_THROW(save_gltf(mesh, "/nonexistent-folder/out.glb"), SaveError);
}

}  // namespace
}  // namespace rgbio
