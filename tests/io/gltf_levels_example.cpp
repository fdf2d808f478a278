// Writes a textured, coloured mesh refined past level 0 both as OBJ and as glTF, for
// gltf_levels_check.py, which reads them back by hand and compares them corner by corner. The mesh:
// textured_grid.h with vertex colours and its one-triangle island. Two meshes are written into
// OUT_FOLDER:
//   adaptive.{obj,gltf,glb}  refined to level 3 in a ball and everywhere once more, displayed positions
//   limit.{obj,gltf,glb}     uniform level 2, limit positions
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "io/base_uvs.h"
#include "io/gltf_export.h"
#include "io/mesh_file.h"
#include "io/obj/obj_error.h"
#include "rgb/lod/requests.h"
#include "textured_grid.h"

namespace {

void write_all(const rgb::Mesh& mesh, const rgbio::SaveOptions& options, const std::filesystem::path& stem) {
    rgbio::save_mesh(mesh, stem.string() + ".obj", options);
    rgbio::export_gltf(mesh, stem.string() + ".gltf", options);
    rgbio::export_gltf(mesh, stem.string() + ".glb", options);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: gltf_levels_example OUT_FOLDER\n";
        return 1;
    }
    const std::filesystem::path folder = argv[1];
    try {
        std::ofstream(folder / "in.obj") << rgbio::test::textured_grid(true, true);
        rgbio::LoadedAsset asset = rgbio::load_asset((folder / "in.obj").string());
        rgbio::SaveOptions options;
        options.attributes = asset.attributes;
        options.uvs = rgbio::uv_layout(asset.uvs, asset.mesh, std::nullopt);
        options.state = false;
        rgb::Mesh adaptive = asset.mesh;
        rgb::set_level(adaptive, 3, rgb::Sphere{{2, 1.5, 0}, 1.2});
        rgb::LevelRequest everywhere;
        everywhere.kind = rgb::RequestKind::Refine;
        everywhere.level = 1;
        rgb::apply_request(adaptive, everywhere);
        write_all(adaptive, options, folder / "adaptive");
        rgb::Mesh uniform = asset.mesh;
        rgb::set_level(uniform, 2);
        options.positions = rgbio::SavedPositions::Limit;
        write_all(uniform, options, folder / "limit");
    } catch (const std::exception& e) {
        std::cerr << e.what() << '\n';
        return 1;
    }
    return 0;
}
