#include "io/base_uvs.h"

#include <algorithm>

#include "io/mesh_file.h"
#include "io/obj_reader.h"
#include "rgb/face_location.h"

namespace rgbio {

namespace {

bool every_corner_has_one(const LoadedMesh& loaded) {
    return std::none_of(loaded.triangle_texcoords.begin(), loaded.triangle_texcoords.end(), [](const auto& t) {
        return std::find(t.begin(), t.end(), kNoIndex) != t.end();
    });
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
    if (!every_corner_has_one(loaded)) {
        warnings.push_back("texture coordinates dropped: some face corners have none (f v without /vt), and subdividing "
                           "them needs one at every corner");
        return std::nullopt;
    }
    if (!loaded.adaptive) {
        rgb::UvChannel uvs;
        uvs.values = loaded.texcoords;
        uvs.corners = loaded.triangle_texcoords;
        return uvs;
    }
    if (mesh.num_vertices() == mesh.num_base_vertices()) return from_base_faces_in_slots(loaded, mesh);
    warnings.push_back("texture coordinates dropped: the file is a refined mesh whose rgbsub state has no base-uvs "
                       "section, so its UVs cannot be put back on the base mesh");
    return std::nullopt;
}

MeshWithUvs load_mesh_with_uvs(const std::string& path, std::vector<std::string>& warnings, const ReadOptions& options) {
    LoadedMesh loaded = read_obj_file(path, options);
    warnings.insert(warnings.end(), loaded.warnings.begin(), loaded.warnings.end());
    rgb::Mesh mesh = loaded.adaptive ? std::move(*loaded.adaptive) : build_mesh(loaded);
    std::optional<rgb::UvChannel> uvs = base_uv_channel(loaded, mesh, warnings);
    return {std::move(mesh), std::move(uvs)};
}

std::shared_ptr<const rgb::UvLayout> uv_layout(const std::optional<rgb::UvChannel>& channel, const rgb::Mesh& mesh,
                                               std::optional<rgb::UvInterpolation> interpolation) {
    if (!channel) return nullptr;
    rgb::UvChannel uvs = *channel;
    if (interpolation) uvs.interpolation = *interpolation;
    return std::make_shared<const rgb::UvLayout>(mesh.base(), std::move(uvs));
}

}  // namespace rgbio
