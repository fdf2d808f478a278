#pragma once
// Draws an rgb::Mesh with OpenGL 3.3 core, in a GLFW window or an OffscreenContext alike: the caller
// makes a context current and loads GL (gladLoadGL) before constructing it.
//
// The GPU copy of the mesh follows the core's change observer: draw() (or sync()) uploads only the
// face slots an edit touched. Modes are uniforms, so switching costs nothing except the limit
// positions, which rebuild the buffer.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "render/camera.h"
#include "render/surface_geometry.h"

namespace rgb {
class Mesh;
}

namespace render {

enum class Shading { Smooth, Flat };
// Material, VertexColour, Checker (a checker pattern over the texture coordinates) and Texture (each
// material's diffuse texture over the texture coordinates) show the geometry's SurfaceAppearance;
// faces the file gives no such data have the plain colour (Checker: the cell of (0, 0)). Texture shows
// a material without a texture (or a face without texture coordinates) in its diffuse colour, and one
// whose texture could not be read as the checker. DetailDistance is the heat map of each face's distance
// to the dense mesh of a cage with detail (colour_map.h's bands, with a legend); a mesh without detail
// shows the plain colour. Matcap shades the surface from a lit clay sphere (a "material capture", made
// in the shader) looked up by the normal as the camera sees it: lighting fixed to the view, which
// shows the surface's shape and small detail more clearly than the headlight.
enum class Colouring { Plain, RgbType, Level, Material, VertexColour, Checker, Texture, DetailDistance, Matcap };

// A circle on the surface: where a sphere around `centre` cuts it.
struct BrushCursor {
    glm::vec3 centre{0.0f};
    float radius = 0.1f;
    glm::vec3 colour{1.0f, 0.55f, 0.0f};
};

struct RenderOptions {
    Shading shading = Shading::Smooth;
    Colouring colouring = Colouring::Plain;
    bool wireframe = false;
    float wire_width_px = 1.0f;
    PositionSource positions = PositionSource::Displayed;
    bool base_mesh_overlay = false;
    bool sharp_edges = true;  // edges along tagged base edges as coloured lines (when there are any)
    bool legend = true;  // of the heat maps: shown with Colouring::Level and Colouring::DetailDistance
    float bottom_inset_px = 0.0f;  // a strip at the bottom that overlays (the legend) keep clear of
    std::optional<BrushCursor> brush;
    glm::vec3 background{1.0f};
};

struct UploadStats {
    std::uint64_t total_bytes = 0;      // since attach
    std::uint64_t last_sync_bytes = 0;  // by the most recent sync that had changes
    std::size_t last_sync_ranges = 0;
};

class Renderer {
public:
    Renderer();  // compiles the shaders; throws ShaderError
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Starts following `mesh` (which must outlive the attachment) and uploads it whole.
    void attach(rgb::Mesh& mesh);
    void detach();
    // Instead of a copy of its own, draws `geometry` of `mesh`, kept current by its owner (the
    // editor's document, which picks on it too), both to outlive the renderer's use of them:
    // `changed` are the slots changed since the previous call, or everything when `rebuilt`.
    void show(const rgb::Mesh& mesh, const SurfaceGeometry& geometry, std::span<const SlotRange> changed, bool rebuilt);

    // Uploads what changed since the last sync.
    void sync();
    // Rebuilds and uploads everything (what an observer-less renderer would do after each edit).
    void reupload_all();
    void set_positions(PositionSource source);
    // Whether the attached mesh's geometry measures each face's distance to the dense mesh
    // (SurfaceGeometry::set_detail_distance); draw() turns it on with Colouring::DetailDistance only.
    void set_detail_distance(bool on);
    // What the attached mesh's faces look like (surface_appearance.h), for the appearance modes; until
    // the next attach or detach.
    void set_appearance(std::shared_ptr<const SurfaceAppearance> appearance);

    // Clears the viewport and draws the mesh seen by `camera`.
    void draw(const OrbitCamera& camera, const RenderOptions& options, glm::ivec2 viewport);

    // Of the attached mesh at the current positions, and of the base mesh (which encloses a
    // subdivision surface) if asked, for framing the base mesh overlay too.
    BoundingSphere bounds(bool with_base_mesh = false) const;
    const SurfaceGeometry& geometry() const;
    const UploadStats& upload_stats() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace render
