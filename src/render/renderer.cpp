#include "render/renderer.h"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include <glad/gl.h>

#include "render/base_mesh_lines.h"
#include "render/colour_map.h"
#include "render/gl_objects.h"
#include "render/level_legend.h"
#include "render/mesh_changes.h"
#include "render/shader_program.h"
#include "render/sharp_edge_lines.h"
#include "render/surface_buffer.h"
#include "rgb/mesh/mesh.h"

namespace render {
namespace {

constexpr glm::vec3 kWireColour{0.12f, 0.12f, 0.12f};
constexpr glm::vec3 kBackColour{0.62f, 0.36f, 0.32f};
constexpr glm::vec3 kBaseMeshColour{0.1f, 0.1f, 0.1f};
constexpr glm::vec3 kSharpEdgeColour{0.85f, 0.05f, 0.55f};
constexpr glm::vec3 kLegendTextColour{0.1f, 0.1f, 0.1f};
constexpr float kBrushWidthPx = 2.0f;
constexpr float kOverlayDepthBias = 1e-3f;
static_assert(kDistanceBands == 11, "shaders/surface.frag's kDistanceBands");

// A vertex array over one tightly packed buffer, for the small line and overlay geometry.
class SimpleVertices {
public:
    template <class Vertex>
    void upload(const std::vector<Vertex>& vertices) {
        glBindBuffer(GL_ARRAY_BUFFER, buffer_.get());
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)), vertices.data(), GL_DYNAMIC_DRAW);
        count_ = static_cast<GLsizei>(vertices.size());
    }
    // Attribute `index` has `components` floats at `offset` bytes within a vertex of `stride` bytes.
    void attribute(GLuint index, GLint components, std::size_t stride, std::size_t offset) {
        glBindVertexArray(vertex_array_.get());
        glBindBuffer(GL_ARRAY_BUFFER, buffer_.get());
        glEnableVertexAttribArray(index);
        glVertexAttribPointer(index, components, GL_FLOAT, GL_FALSE, static_cast<GLsizei>(stride),
                              reinterpret_cast<const void*>(offset));
        glBindVertexArray(0);
    }
    void draw(GLenum primitive) const {
        if (count_ == 0) return;
        glBindVertexArray(vertex_array_.get());
        glDrawArrays(primitive, 0, count_);
        glBindVertexArray(0);
    }

private:
    GlVertexArray vertex_array_;
    GlBuffer buffer_;
    GLsizei count_ = 0;
};

// The appearance's textures as the 2D array texture the surface shader samples (unit 0).
class TextureArray {
public:
    // Uploads `appearance`'s textures unless they are up already.
    void show(const std::shared_ptr<const SurfaceAppearance>& appearance) {
        if (appearance == shown_) return;
        shown_ = appearance;
        const TextureLayers empty;
        const TextureLayers& layers = appearance ? appearance->textures : empty;
        glBindTexture(GL_TEXTURE_2D_ARRAY, texture_.get());
        glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA8, layers.width, layers.height, static_cast<GLsizei>(layers.count()), 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, layers.count() > 0 ? layers.rgba.data() : nullptr);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_REPEAT);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        if (layers.count() > 0) glGenerateMipmap(GL_TEXTURE_2D_ARRAY);
        glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    }
    void bind() const {
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D_ARRAY, texture_.get());
    }

private:
    GlTexture texture_;
    // Held, so that a new appearance can never reuse the address of the one uploaded.
    std::shared_ptr<const SurfaceAppearance> shown_;
};

}  // namespace

struct Renderer::State {
    ShaderProgram surface_program{"surface.vert", "surface.frag"};
    ShaderProgram lines_program{"lines.vert", "lines.frag"};
    ShaderProgram overlay_program{"overlay.vert", "overlay.frag"};
    SurfaceBuffer surface;
    SimpleVertices base_lines;
    SimpleVertices sharp_lines;  // follows the surface: uploaded again whenever it changes
    SharpEdgeLines sharp_edges;
    SimpleVertices overlay;
    TextureArray textures;
    SurfaceGeometry geometry;
    rgb::Mesh* mesh = nullptr;
    std::unique_ptr<MeshChanges> changes;
    UploadStats stats;
    // What show() draws, when it is used instead of attach().
    const rgb::Mesh* shown_mesh = nullptr;
    const SurfaceGeometry* shown = nullptr;

    const SurfaceGeometry& drawn() const { return shown ? *shown : geometry; }

    // The sharp edges after the slots `changed` of `mesh` were rewritten (all of them: `rebuilt`).
    void follow_sharp_edges(const rgb::Mesh& shown_mesh, std::span<const SlotRange> changed, bool rebuilt) {
        if (rebuilt) sharp_edges.rebuild(shown_mesh);
        else sharp_edges.update(shown_mesh, changed);
        sharp_lines.upload(sharp_edges.lines(drawn()));
    }

    void count_upload(std::uint64_t before, std::size_t ranges) {
        stats.last_sync_bytes = surface.bytes_uploaded() - before;
        stats.last_sync_ranges = ranges;
        stats.total_bytes = surface.bytes_uploaded();
    }
};

Renderer::Renderer() : state_(std::make_unique<State>()) {
    state_->base_lines.attribute(0, 3, sizeof(glm::vec3), 0);
    state_->sharp_lines.attribute(0, 3, sizeof(glm::vec3), 0);
    state_->overlay.attribute(0, 2, sizeof(OverlayVertex), offsetof(OverlayVertex, pixel));
    state_->overlay.attribute(1, 3, sizeof(OverlayVertex), offsetof(OverlayVertex, colour));
}

Renderer::~Renderer() = default;

void Renderer::attach(rgb::Mesh& mesh) {
    detach();
    state_->shown = nullptr;
    state_->shown_mesh = nullptr;
    state_->mesh = &mesh;
    state_->changes = std::make_unique<MeshChanges>(mesh);
    state_->base_lines.upload(base_mesh_lines(mesh));
    reupload_all();
}

void Renderer::detach() {
    state_->changes.reset();
    state_->mesh = nullptr;
    state_->geometry = SurfaceGeometry(state_->geometry.source());
    state_->surface.upload_all({});
    state_->base_lines.upload(std::vector<glm::vec3>{});
    state_->sharp_edges = SharpEdgeLines();
    state_->sharp_lines.upload(std::vector<glm::vec3>{});
}

void Renderer::show(const rgb::Mesh& mesh, const SurfaceGeometry& geometry, std::span<const SlotRange> changed, bool rebuilt) {
    State& s = *state_;
    if (s.mesh != nullptr) detach();
    const std::uint64_t before = s.surface.bytes_uploaded();
    if (rebuilt || s.shown != &geometry || s.shown_mesh != &mesh) {
        s.shown = &geometry;
        s.shown_mesh = &mesh;
        s.base_lines.upload(base_mesh_lines(mesh));
        s.surface.upload_all(geometry.vertices(), geometry.appearance_vertices());
        s.count_upload(before, 1);
        s.follow_sharp_edges(mesh, {}, true);
    } else if (!changed.empty()) {
        s.surface.upload(geometry.vertices(), geometry.appearance_vertices(), changed);
        s.count_upload(before, changed.size());
        s.follow_sharp_edges(mesh, changed, false);
    }
}

void Renderer::sync() {
    State& s = *state_;
    if (s.mesh == nullptr || s.changes->empty()) return;
    const std::uint64_t before = s.surface.bytes_uploaded();
    const std::vector<SlotRange> ranges = s.geometry.update(*s.mesh, *s.changes);
    s.changes->clear();
    s.surface.upload(s.geometry.vertices(), s.geometry.appearance_vertices(), ranges);
    s.count_upload(before, ranges.size());
    s.follow_sharp_edges(*s.mesh, ranges, false);
}

void Renderer::reupload_all() {
    State& s = *state_;
    if (s.mesh == nullptr) return;
    const std::uint64_t before = s.surface.bytes_uploaded();
    s.changes->clear();
    s.geometry.rebuild(*s.mesh);
    s.surface.upload_all(s.geometry.vertices(), s.geometry.appearance_vertices());
    s.count_upload(before, 1);
    s.follow_sharp_edges(*s.mesh, {}, true);
}

void Renderer::set_positions(PositionSource source) {
    if (state_->geometry.source() == source) return;
    state_->geometry.set_source(source);
    reupload_all();
}

void Renderer::set_detail_distance(bool on) {
    if (state_->geometry.detail_distance() == on) return;
    state_->geometry.set_detail_distance(on);
    reupload_all();
}

void Renderer::set_appearance(std::shared_ptr<const SurfaceAppearance> appearance) {
    state_->geometry.set_appearance(std::move(appearance));
    reupload_all();
}

void Renderer::draw(const OrbitCamera& camera, const RenderOptions& options, glm::ivec2 viewport) {
    State& s = *state_;
    set_positions(options.positions);
    set_detail_distance(options.colouring == Colouring::DetailDistance);
    sync();

    glViewport(0, 0, viewport.x, viewport.y);
    glClearColor(options.background.r, options.background.g, options.background.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    const glm::mat4 view_projection =
        camera.view_projection(static_cast<float>(viewport.x) / static_cast<float>(std::max(viewport.y, 1)));

    const int max_level = s.drawn().max_face_level();
    std::vector<glm::vec3> level_colours(kMaxLevelColours);
    for (int level = 0; level < kMaxLevelColours; ++level)
        level_colours[static_cast<std::size_t>(level)] = level_colour(level);
    const glm::vec3 rgb_colours[3] = {rgb_type_colour(rgb::Colour::Green), rgb_type_colour(rgb::Colour::Red),
                                      rgb_type_colour(rgb::Colour::Blue)};

    const ShaderProgram& surface = s.surface_program;
    surface.use();
    surface.set("u_view_projection", view_projection);
    // Shading normalises vectors between positions; for scenes far from unit size their squared
    // lengths leave float's range. A power of two of about 1 / distance scales them exactly.
    const float shading_scale = std::exp2(-std::round(std::log2(camera.distance)));
    surface.set("u_shading_scale", shading_scale);
    surface.set("u_eye", camera.eye() * shading_scale);
    surface.set("u_view_rotation", glm::mat3(camera.view()));
    surface.set("u_flat", options.shading == Shading::Flat);
    surface.set("u_colouring", static_cast<int>(options.colouring));
    surface.set("u_plain_colour", kPlainColour);
    surface.set_array("u_rgb_colours", rgb_colours, 3);
    surface.set_array("u_level_colours", level_colours.data(), kMaxLevelColours);
    std::vector<glm::vec3> distance_colours(kDistanceBands);
    for (int band = 0; band < kDistanceBands; ++band) distance_colours[static_cast<std::size_t>(band)] = distance_colour(band);
    surface.set_array("u_distance_colours", distance_colours.data(), kDistanceBands);
    const std::optional<double> distance_scale = s.drawn().distance_scale();
    surface.set("u_distance_measured", distance_scale.has_value());
    const glm::vec3 checker_colours[2] = {checker_colour(0), checker_colour(1)};
    surface.set_array("u_checker_colours", checker_colours, 2);
    surface.set("u_checker_cells", kCheckerCells);
    s.textures.show(s.drawn().appearance());
    s.textures.bind();
    surface.set("u_textures", 0);
    surface.set("u_wire", options.wireframe);
    surface.set("u_wire_width", options.wire_width_px);
    surface.set("u_wire_colour", kWireColour);
    surface.set("u_back_colour", kBackColour);
    surface.set("u_brush", options.brush.has_value());
    if (options.brush) {
        surface.set("u_brush_centre", options.brush->centre * shading_scale);
        surface.set("u_brush_radius", options.brush->radius * shading_scale);
        surface.set("u_brush_width", kBrushWidthPx);
        surface.set("u_brush_colour", options.brush->colour);
    }
    s.surface.draw();

    const auto draw_lines = [&](const SimpleVertices& lines, const glm::vec3& colour) {
        s.lines_program.use();
        s.lines_program.set("u_view_projection", view_projection);
        s.lines_program.set("u_depth_bias", kOverlayDepthBias);
        s.lines_program.set("u_colour", colour);
        lines.draw(GL_LINES);
    };
    if (options.base_mesh_overlay) draw_lines(s.base_lines, kBaseMeshColour);
    if (options.sharp_edges) draw_lines(s.sharp_lines, kSharpEdgeColour);

    const glm::ivec2 legend_area{viewport.x, viewport.y - static_cast<int>(options.bottom_inset_px)};
    std::vector<OverlayVertex> legend;
    if (options.legend && options.colouring == Colouring::Level) legend = level_legend(max_level, legend_area, kLegendTextColour);
    if (options.legend && options.colouring == Colouring::DetailDistance && distance_scale)
        legend = distance_legend(*distance_scale, legend_area, kLegendTextColour);
    if (!legend.empty()) {
        glDisable(GL_DEPTH_TEST);
        s.overlay.upload(legend);
        s.overlay_program.use();
        s.overlay_program.set("u_viewport_size", glm::vec2(viewport));
        s.overlay.draw(GL_TRIANGLES);
        glEnable(GL_DEPTH_TEST);
    }
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    glUseProgram(0);
}

BoundingSphere Renderer::bounds(bool with_base_mesh) const {
    const rgb::Mesh* mesh = state_->shown ? state_->shown_mesh : state_->mesh;
    if (mesh == nullptr) return {};
    std::vector<glm::vec3> points = state_->drawn().live_positions(*mesh);
    if (with_base_mesh)
        for (std::uint32_t i = 0; i < mesh->num_base_vertices(); ++i) points.emplace_back(mesh->insertion_position(rgb::VertexId(i)));
    return bounding_sphere(points);
}

const SurfaceGeometry& Renderer::geometry() const { return state_->drawn(); }

const UploadStats& Renderer::upload_stats() const { return state_->stats; }

}  // namespace render
