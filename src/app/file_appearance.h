#pragma once
// The editor's preview of what a file says about its look: the base mesh's materials, vertex
// colours and texture coordinates (rgbio::BaseAttributes) as the renderer's SurfaceAppearance.
#include <memory>

#include "io/base_attributes.h"
#include "render/surface_appearance.h"

namespace app {

// Null when the file gives none of them. `base_faces`: how many faces the base mesh has.
std::shared_ptr<const render::SurfaceAppearance> file_appearance(const rgbio::BaseAttributes& attributes, std::size_t base_faces);

}  // namespace app
