#pragma once
// The editor's preview of what a file says about its look: the base mesh's materials (diffuse
// colours and textures), vertex colours and texture coordinates (rgbio::BaseAttributes and the UV
// channel) as the renderer's SurfaceAppearance. Reads the textures (stb_image: PNG, JPEG, TGA, ...),
// so it runs where the file is read, away from the window's thread.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/base_attributes.h"
#include "render/surface_appearance.h"
#include "rgb/values/uv_layout.h"

namespace app {

// Null when the file gives none of them. `base_faces`: how many faces the base mesh has. A texture
// that cannot be read is a warning appended to `warnings` (naming the file); its faces show the
// texture checker.
std::shared_ptr<const render::SurfaceAppearance> file_appearance(const rgbio::BaseAttributes& attributes,
                                                                 const std::optional<rgb::UvChannel>& uvs, std::size_t base_faces,
                                                                 std::vector<std::string>& warnings);

}  // namespace app
