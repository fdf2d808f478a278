#include "app/file_appearance.h"

#include <filesystem>
#include <map>
#include <stdexcept>

#include "io/gltf/gltf_writer.h"
#include "io/obj/printable_text.h"
#include "render/image.h"

namespace app {
namespace {

// The diffuse textures the base faces' materials name, read once per file: per material, its layer
// of `images` or kNoTexture / kUnreadableTexture. Unreadable files become one warning.
class TextureReader {
public:
    std::uint32_t layer_of(const rgbio::Material& material) {
        if (material.diffuse_texture.empty()) return render::kNoTexture;
        const auto known = layers_.find(material.diffuse_texture);
        if (known != layers_.end()) return known->second;
        std::uint32_t layer = render::kUnreadableTexture;
        try {
            std::error_code error;
            if (!std::filesystem::is_regular_file(material.diffuse_texture, error)) throw std::runtime_error("there is no such file");
            images_.push_back(reader_.read(material.diffuse_texture));
            layer = static_cast<std::uint32_t>(images_.size() - 1);
        } catch (const std::exception& e) {
            if (unreadable_++ == 0) {
                first_texture_ = rgbio::quoted_file_text(material.diffuse_texture, 200) + " of material " + rgbio::quoted_file_text(material.name);
                first_reason_ = e.what();
            }
        }
        layers_.emplace(material.diffuse_texture, layer);
        return layer;
    }
    const std::vector<render::Image>& images() const { return images_; }
    void warn(std::vector<std::string>& warnings) const {
        if (unreadable_ == 1)
            warnings.push_back("diffuse texture (map_Kd) " + first_texture_ + " cannot be shown (" + first_reason_ +
                               "); its faces show the texture checker");
        if (unreadable_ > 1)
            warnings.push_back(std::to_string(unreadable_) + " diffuse textures (map_Kd) cannot be shown, the first " + first_texture_ + " (" +
                               first_reason_ + "); their faces show the texture checker");
    }

private:
    std::map<std::string, std::uint32_t> layers_;
    std::vector<render::Image> images_;
    render::BoundedImageReader reader_;
    std::size_t unreadable_ = 0;
    std::string first_texture_, first_reason_;
};

}  // namespace

std::shared_ptr<const render::SurfaceAppearance> file_appearance(const rgbio::BaseAttributes& attributes,
                                                                 const std::optional<rgb::UvChannel>& uvs, std::size_t base_faces,
                                                                 std::vector<std::string>& warnings) {
    render::SurfaceAppearance appearance;
    const std::vector<std::uint32_t> material_of_face = rgbio::material_indices(attributes.labels.materials, attributes.materials);
    if (!material_of_face.empty()) {
        TextureReader textures;
        appearance.face_colours.resize(base_faces);
        appearance.face_textures.assign(base_faces, render::kNoTexture);
        for (std::size_t f = 0; f < base_faces; ++f) {
            if (material_of_face[f] == rgbio::kNoIndex) continue;
            const rgbio::Material& material = attributes.materials[material_of_face[f]];
            appearance.face_colours[f] = glm::vec3(material.diffuse);
            appearance.face_textures[f] = textures.layer_of(material);
        }
        appearance.textures = render::texture_layers(textures.images());
        textures.warn(warnings);
    }
    appearance.vertex_colours = attributes.colours;
    appearance.uvs = uvs;
    if (appearance.empty()) return nullptr;
    return std::make_shared<const render::SurfaceAppearance>(std::move(appearance));
}

}  // namespace app
