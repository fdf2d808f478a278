// Writes a small known mesh as OUT_FOLDER/out.gltf and OUT_FOLDER/out.glb for gltf_export_check.py,
// which reads them back without tinygltf. The mesh (all in the plane z = 0):
//   vertices 0 (0,0) 1 (1,0) 2 (1,1) 3 (0,1) 4 (2,0.5) 5 (2,1.5), normals (0,0,2)
//   triangles 0 1 2 and 0 2 3 (material 1, textured; texture coordinates 0 1 2 and 0 2 3),
//   1 4 2 (material 0, a colour; texture coordinates 4 5 6: a seam at vertices 1 and 2),
//   2 4 5 (no material, no texture coordinates)
//   texture coordinates (0,0) (1,0) (1,1) (0,1) (0.25,0.25) (0.75,0.5) (0.25,0.75)
#include <filesystem>
#include <iostream>

#include "io/gltf/gltf_writer.h"
#include "io/obj/obj_error.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: gltf_export_example OUT_FOLDER\n";
        return 1;
    }
    const std::filesystem::path folder = argv[1];
    rgbio::GltfMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0.5, 0}, {2, 1.5, 0}};
    mesh.normals.assign(6, glm::dvec3(0, 0, 2));
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 2}, {2, 4, 5}};
    mesh.texcoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.25, 0.25}, {0.75, 0.5}, {0.25, 0.75}};
    constexpr std::uint32_t none = rgbio::kNoIndex;
    mesh.triangle_texcoords = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {none, none, none}};
    mesh.triangle_materials = {1, 1, 0, none};
    mesh.materials = {{.name = "Painted", .diffuse = {0.25, 0.5, 0.75}, .diffuse_texture = "", .library = "a.mtl"},
                      {.name = "Skin", .diffuse = {0.8, 0.8, 0.8}, .diffuse_texture = (folder / "my textures/skin 1.png").string(),
                       .library = "a.mtl"}};
    try {
        rgbio::save_gltf(mesh, (folder / "out.gltf").string());
        rgbio::save_gltf(mesh, (folder / "out.glb").string());
    } catch (const rgbio::SaveError& e) {
        std::cerr << e.what() << '\n';
        return 1;
    }
    return 0;
}
