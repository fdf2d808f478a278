// Writes a textured, coloured mesh refined past level 0 as glTF, and beside it what the mesh in
// memory holds, corner by corner, for gltf_levels_check.py, which reads the glTF by hand and compares
// the two: no writer of ours (OBJ or other) stands between the mesh and the check. The mesh:
// textured_grid.h with vertex colours and its one-triangle island. Two meshes are written into
// OUT_FOLDER:
//   adaptive.{gltf,glb,corners}  refined to level 3 in a ball and everywhere once more, displayed positions
//   limit.{gltf,glb,corners}     uniform level 2, limit positions
// A .corners file has one line per face corner, three per live face in slot order: the vertex slot,
// its position, the corner's UV and the vertex colour, each number in shortest round-trip form,
// taken straight from the core (displayed or limit position, displayed or limit UV, the colour
// channel at the same level).
#include <charconv>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "io/base_uvs.h"
#include "io/gltf_export.h"
#include "io/mesh_file.h"
#include "io/obj/obj_error.h"
#include "rgb/lod/requests.h"
#include "rgb/values/loop_geometry.h"
#include "rgb/values/mesh_uvs.h"
#include "rgb/values/uv_evaluator.h"
#include "rgb/values/vertex_channel.h"
#include "textured_grid.h"
#include "support/set_level.h"

namespace {

std::string shortest(double x) {
    char text[32];
    return std::string(text, std::to_chars(text, text + sizeof text, x).ptr);
}

void write_corners(const rgb::Mesh& mesh, const rgbio::SaveOptions& options, const std::filesystem::path& path) {
    const bool limit = options.positions == rgbio::SavedPositions::Limit;
    const std::vector<glm::dvec3> colours = rgb::vertex_channel_values(
        mesh, options.attributes->colours, limit ? rgb::ChannelLevel::Limit : rgb::ChannelLevel::Displayed);
    rgb::UvEvaluator uvs(mesh.base(), *options.uvs);
    std::ofstream out(path);
    for (rgb::FaceId f : mesh.faces())
        for (int i = 0; i < 3; ++i) {
            const rgb::VertexId v = mesh.face_vertices(f)[i];
            const glm::dvec3 p = limit ? rgb::limit_position_uncached(mesh, v) : rgb::displayed_position(mesh, v);
            const glm::dvec2 uv = limit ? rgb::limit_uv(mesh, uvs, f, i) : rgb::displayed_uv(mesh, uvs, f, i);
            const glm::dvec3& c = colours[v.idx];
            out << v.idx;
            for (double x : {p.x, p.y, p.z, uv.x, uv.y, c.x, c.y, c.z}) out << ' ' << shortest(x);
            out << '\n';
        }
    if (!out.flush()) throw std::runtime_error("cannot write " + path.string());
}

void write_all(const rgb::Mesh& mesh, const rgbio::SaveOptions& options, const std::filesystem::path& stem) {
    write_corners(mesh, options, stem.string() + ".corners");
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
        rgbtest::set_level(adaptive, 3, rgb::Sphere{{2, 1.5, 0}, 1.2});
        rgb::LevelRequest everywhere;
        everywhere.kind = rgb::RequestKind::Refine;
        everywhere.level = 1;
        rgb::apply_request(adaptive, everywhere);
        write_all(adaptive, options, folder / "adaptive");
        rgb::Mesh uniform = asset.mesh;
        rgbtest::set_level(uniform, 2);
        options.positions = rgbio::SavedPositions::Limit;
        write_all(uniform, options, folder / "limit");
    } catch (const std::exception& e) {
        std::cerr << e.what() << '\n';
        return 1;
    }
    return 0;
}
