#pragma once
// One-shot headless rendering: an OSMesa context, a Renderer, a camera framing the mesh, one frame.
// What `rgbsub render` and the screenshot tests use; same input, same bytes.
#include <functional>
#include <memory>

#include <glm/vec2.hpp>

#include "render/camera.h"
#include "render/image.h"
#include "render/renderer.h"

namespace rgb {
class Mesh;
}

namespace render {

struct HeadlessView {
    glm::ivec2 size{800, 600};
    float azimuth_deg = 30.0f;
    float elevation_deg = 20.0f;
};

// The camera that frames `bounds` for `view`.
OrbitCamera framing_camera(const BoundingSphere& bounds, const HeadlessView& view);

// Renders `mesh` (with `appearance`, if any) framed automatically. `before_drawing`, if given, may
// change the mesh for the camera just framed (the screen-space level of detail does); the frame shows
// the changed mesh from that camera. Throws std::runtime_error if no context can be made.
Image render_headless(rgb::Mesh& mesh, const RenderOptions& options, const HeadlessView& view,
                      std::shared_ptr<const SurfaceAppearance> appearance = nullptr,
                      const std::function<void(const OrbitCamera&)>& before_drawing = {});

}  // namespace render
