#include "app/file_appearance.h"

#include <algorithm>

#include "io/gltf_writer.h"

namespace app {

std::shared_ptr<const render::SurfaceAppearance> file_appearance(const rgbio::BaseAttributes& attributes, std::size_t base_faces) {
    render::SurfaceAppearance appearance;
    const std::vector<std::uint32_t> material_of_face = rgbio::material_indices(attributes.labels.materials, attributes.materials);
    if (!material_of_face.empty()) {
        appearance.face_colours.resize(base_faces);
        for (std::size_t f = 0; f < base_faces; ++f)
            if (material_of_face[f] != rgbio::kNoIndex) appearance.face_colours[f] = glm::vec3(attributes.materials[material_of_face[f]].diffuse);
    }
    for (const glm::dvec3& colour : attributes.colours) appearance.vertex_colours.emplace_back(colour);
    if (!attributes.triangle_texcoords.empty()) {
        appearance.corner_texcoords.resize(base_faces);
        for (std::size_t f = 0; f < base_faces; ++f) {
            const auto& corners = attributes.triangle_texcoords[f];
            // A face with a corner the file gives no texture coordinate has none.
            if (std::ranges::find(corners, rgbio::kNoIndex) != corners.end()) continue;
            appearance.corner_texcoords[f] = {glm::vec2(attributes.texcoords[corners[0]]), glm::vec2(attributes.texcoords[corners[1]]),
                                              glm::vec2(attributes.texcoords[corners[2]])};
        }
    }
    if (appearance.empty()) return nullptr;
    return std::make_shared<const render::SurfaceAppearance>(std::move(appearance));
}

}  // namespace app
