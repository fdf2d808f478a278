// The GL side of the renderer: shaders, incremental uploads.
#include <gtest/gtest.h>

#include <string>

#include "render/embedded_shaders.h"
#include "render/headless.h"
#include "render/offscreen_context.h"
#include "render/renderer.h"
#include "render/shader_program.h"
#include "rgb/lod/refine.h"
#include "rgb/mesh/mesh.h"
#include "test_meshes.h"

namespace {

TEST(Shaders, EveryShaderFileIsEmbedded) {
    for (const char* name : {"surface.vert", "surface.frag", "lines.vert", "lines.frag", "overlay.vert", "overlay.frag"})
        EXPECT_NE(render::embedded_shader(name).source.find("#version 330 core"), std::string_view::npos) << name;
    EXPECT_THROW(render::embedded_shader("missing.frag"), std::out_of_range);
}

TEST(Shaders, CompileErrorNamesTheFileAndQuotesTheDriver) {
    render::OffscreenContext context(8, 8);
    const render::EmbeddedShader broken{"broken.frag", "#version 330 core\nout vec4 c;\nvoid main() { c = undeclared; }\n"};
    try {
        render::ShaderProgram program(render::embedded_shader("surface.vert"), broken);
        FAIL() << "a shader using an undeclared name compiled";
    } catch (const render::ShaderError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("shaders/broken.frag"), std::string::npos) << message;
        EXPECT_NE(message.find("undeclared"), std::string::npos) << "the driver's log names the culprit: " << message;
    }
}

// After an edit the renderer uploads only the slots it touched, and the picture is the one a fresh
// full upload of the edited mesh gives.
TEST(Renderer, IncrementalUploadDrawsWhatAFullUploadDraws) {
    const render::HeadlessView view{{160, 160}, 20.0f, 10.0f};
    rgb::Mesh mesh = render_test::icosphere(3);
    render::OffscreenContext context(view.size.x, view.size.y);
    render::Renderer renderer;
    renderer.attach(mesh);
    const std::uint64_t full = 3 * sizeof(render::SurfaceVertex) * mesh.face_capacity();
    EXPECT_EQ(renderer.upload_stats().total_bytes, full);

    const render::OrbitCamera camera = render::framing_camera(renderer.bounds(), view);
    render::RenderOptions options;
    options.colouring = render::Colouring::RgbType;
    options.wireframe = true;
    const auto& corners = mesh.face_vertices(rgb::FaceId(7));
    ASSERT_TRUE(rgb::refine_edge(mesh, corners[0], corners[1]));
    renderer.draw(camera, options, view.size);
    const render::Image incremental = context.read_pixels();

    const render::UploadStats& stats = renderer.upload_stats();
    EXPECT_GT(stats.last_sync_bytes, 0u);
    EXPECT_LT(stats.last_sync_bytes, full / 10) << "one split must not re-upload the mesh";
    EXPECT_EQ(stats.total_bytes, full + stats.last_sync_bytes);

    render::Renderer fresh;
    fresh.attach(mesh);
    fresh.draw(camera, options, view.size);
    EXPECT_EQ(context.read_pixels().rgba, incremental.rgba);
}

TEST(Renderer, SwitchingToLimitPositionsRebuildsOnce) {
    rgb::Mesh mesh = render_test::icosphere(1);
    rgb::refine_uniform(mesh, 1);
    render::OffscreenContext context(32, 32);
    render::Renderer renderer;
    renderer.attach(mesh);
    const std::uint64_t full = renderer.upload_stats().total_bytes;
    renderer.set_positions(render::PositionSource::Limit);
    renderer.set_positions(render::PositionSource::Limit);
    EXPECT_EQ(renderer.upload_stats().total_bytes, 2 * full);
    EXPECT_EQ(renderer.geometry().source(), render::PositionSource::Limit);
}

}  // namespace
