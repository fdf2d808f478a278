#include "io/base_uvs.h"

#include "io/base_attributes.h"

#include <algorithm>
#include <span>
#include <unordered_map>

#include "io/mesh_file.h"
#include "io/obj_reader.h"
#include "rgb/mesh/face_location.h"

namespace rgbio {

namespace {

// Whether every triangle has vt at all of its corners or at none.
bool whole_faces(const LoadedMesh& loaded) {
    return std::all_of(loaded.triangle_texcoords.begin(), loaded.triangle_texcoords.end(), [](const auto& t) {
        const auto missing = std::count(t.begin(), t.end(), kNoIndex);
        return missing == 0 || missing == 3;
    });
}

// Faces without vt get placeholder values: (0, 0), one per vertex, so that the edges between them
// and textured faces are seams and the textured side's UVs follow only their own.
void add_placeholders(rgb::UvChannel& uvs, std::span<const rgb::Triangle> triangles) {
    std::unordered_map<std::uint32_t, std::uint32_t> placeholder;
    for (std::uint32_t f = 0; f < uvs.corners.size(); ++f) {
        if (uvs.corners[f][0] != kNoIndex) continue;
        uvs.faces_without_uvs.push_back(f);
        for (std::size_t c = 0; c < 3; ++c) {
            const auto [it, added] = placeholder.emplace(triangles[f][c], static_cast<std::uint32_t>(uvs.values.size()));
            if (added) uvs.values.push_back(glm::dvec2(0.0));
            uvs.corners[f][c] = it->second;
        }
    }
}

// A saved mesh at level 0 shows its base faces in its own slot order (the f lines), each rotated
// to start anywhere: the UVs of base face g are those of the f line that is g.
rgb::UvChannel from_base_faces_in_slots(const LoadedMesh& loaded, const rgb::Mesh& mesh) {
    rgb::UvChannel uvs;
    uvs.values = loaded.texcoords;
    uvs.corners.resize(mesh.base().num_faces());
    std::size_t line = 0;
    for (rgb::FaceId f : mesh.faces()) {
        const std::uint32_t g = rgb::base_face_of(mesh, f);
        const rgb::Triangle& t = mesh.base().face(g);
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k)
                if (t[static_cast<std::size_t>(k)] == mesh.face_vertices(f)[static_cast<std::size_t>(c)].idx)
                    uvs.corners[g][static_cast<std::size_t>(k)] = loaded.triangle_texcoords[line][static_cast<std::size_t>(c)];
        ++line;
    }
    return uvs;
}

}  // namespace

std::optional<rgb::UvChannel> base_uv_channel(const LoadedMesh& loaded, const rgb::Mesh& mesh, std::vector<std::string>& warnings) {
    if (loaded.base_uvs) return loaded.base_uvs;
    if (loaded.triangle_texcoords.empty()) return std::nullopt;
    if (!whole_faces(loaded)) {
        warnings.push_back("texture coordinates dropped: some faces have them at some corners only (f v/vt v v/vt), "
                           "and subdividing them needs one at every corner of a textured face");
        return std::nullopt;
    }
    std::optional<rgb::UvChannel> uvs;
    if (!loaded.adaptive) {
        uvs.emplace();
        uvs->values = loaded.texcoords;
        uvs->corners = loaded.triangle_texcoords;
    } else if (mesh.num_vertices() == mesh.num_base_vertices()) {
        uvs = from_base_faces_in_slots(loaded, mesh);
    } else {
        warnings.push_back("texture coordinates dropped: the file is a refined mesh whose rgbsub state has no base-uvs "
                           "section, so its UVs cannot be put back on the base mesh");
        return std::nullopt;
    }
    add_placeholders(*uvs, mesh.base().faces());
    return uvs;
}

MeshWithUvs load_mesh_with_uvs(const std::string& path, std::vector<std::string>& warnings, const ReadOptions& options) {
    LoadedAsset asset = load_asset(path, &warnings, options);
    return {std::move(asset.mesh), std::move(asset.uvs)};
}

std::shared_ptr<const rgb::UvLayout> uv_layout(const std::optional<rgb::UvChannel>& channel, const rgb::Mesh& mesh,
                                               std::optional<rgb::UvInterpolation> interpolation) {
    if (!channel) return nullptr;
    rgb::UvChannel uvs = *channel;
    if (interpolation) uvs.interpolation = *interpolation;
    return std::make_shared<const rgb::UvLayout>(mesh.base(), std::move(uvs));
}

}  // namespace rgbio
