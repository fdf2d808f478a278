#include "render/headless.h"

#include "render/offscreen_context.h"

namespace render {

OrbitCamera framing_camera(const BoundingSphere& bounds, const HeadlessView& view) {
    return frame_sphere(bounds, view.azimuth_deg, view.elevation_deg,
                        static_cast<float>(view.size.x) / static_cast<float>(view.size.y));
}

Image render_headless(rgb::Mesh& mesh, const RenderOptions& options, const HeadlessView& view,
                      std::shared_ptr<const SurfaceAppearance> appearance,
                      const std::function<void(const OrbitCamera&)>& before_drawing) {
    OffscreenContext context(view.size.x, view.size.y);
    Renderer renderer;
    renderer.attach(mesh);
    if (appearance) renderer.set_appearance(std::move(appearance));
    renderer.set_positions(options.positions);
    const OrbitCamera camera = framing_camera(renderer.bounds(options.base_mesh_overlay), view);
    if (before_drawing) before_drawing(camera);
    renderer.draw(camera, options, view.size);
    return context.read_pixels();
}

}  // namespace render
