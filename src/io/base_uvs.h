#pragma once
// The texture coordinates of a loaded file as the base mesh's UV channel (rgb/values/uv_layout.h), from
// which every UV of every adaptive mesh over it follows exactly (rgb/values/uv_evaluator.h): a saved file's
// base-uvs section, a plain file's vt (its triangles are the base faces), or the vt of a saved mesh
// at level 0 (its faces are the base faces, in other slots).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/obj/loaded_mesh.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/uv_layout.h"

namespace rgbio {

// `mesh` is build_mesh(loaded). Without texture coordinates, nothing. Faces without vt are kept as
// UvChannel::faces_without_uvs. Appends a warning, and gives nothing, where the file's UVs cannot be
// put on the base mesh: a face with vt at some corners only, or a refined saved mesh whose state has
// no base-uvs section (written by another program or an older rgbsub).
std::optional<rgb::UvChannel> base_uv_channel(const LoadedMesh& loaded, const rgb::Mesh& mesh, std::vector<std::string>& warnings);

// A mesh file's mesh and its base UV channel (read_obj_file, build_mesh, base_uv_channel); a saved
// mesh is moved out rather than copied (it can be large). Warnings are appended.
struct MeshWithUvs {
    rgb::Mesh mesh;
    std::optional<rgb::UvChannel> uvs;
};
MeshWithUvs load_mesh_with_uvs(const std::string& path, std::vector<std::string>& warnings, const ReadOptions& options = {});

// The channel's layout over the mesh's base mesh, with `interpolation` in place of the channel's
// when given; nullptr without a channel.
std::shared_ptr<const rgb::UvLayout> uv_layout(const std::optional<rgb::UvChannel>& channel, const rgb::Mesh& mesh,
                                               std::optional<rgb::UvInterpolation> interpolation);

}  // namespace rgbio
