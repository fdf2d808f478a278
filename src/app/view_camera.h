#pragma once
// The editor's camera: orbit, pan and zoom on top of render::OrbitCamera, rays through pixels and
// the pixel-to-world scale the brush needs. GL-free, so the input layer is testable without a display.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "render/camera.h"

namespace app {

struct Ray {
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0, 0.0, -1.0};  // unit length
};

class ViewCamera {
public:
    // Frames `scene` from the default angles for a viewport of `viewport` pixels (R, and opening a
    // file); the projection stays as the user chose it.
    void frame(const render::BoundingSphere& scene, glm::ivec2 viewport);
    // Keeps the framing angles and target, only refits the distance (F).
    void refit(const render::BoundingSphere& scene, glm::ivec2 viewport);

    // Mouse deltas in pixels.
    void orbit(glm::vec2 delta_px);
    void pan(glm::vec2 delta_px, glm::ivec2 viewport);
    // Wheel steps: positive zooms in, towards `anchor`, which stays where it is on the screen.
    void zoom(float steps, const glm::dvec3& anchor);
    // Blender's numpad views: looking along an axis of the mesh's frame from its side `axis` names
    // (Front: from +Z, Right: from +X, Top: from +Y, Y up), at the same target and distance.
    enum class Axis { Front, Back, Right, Left, Top, Bottom };
    void look_from(Axis axis);
    // A parallel projection (render::OrbitCamera::orthographic).
    void set_orthographic(bool on);

    const render::OrbitCamera& camera() const { return camera_; }
    // The ray from the eye through pixel `px` (origin top left, y down).
    Ray ray_through(glm::vec2 px, glm::ivec2 viewport) const;
    // World length of one pixel at distance `depth` along the view direction (the same at every
    // depth in a parallel view).
    double world_per_pixel(double depth, glm::ivec2 viewport) const;
    // Distance of `p` from the eye along the view direction.
    double depth_of(const glm::dvec3& p) const;

private:
    void fit_clip_planes();

    render::OrbitCamera camera_;
    render::BoundingSphere scene_;
};

}  // namespace app
