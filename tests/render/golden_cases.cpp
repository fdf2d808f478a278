#include "golden_cases.h"

#include "rgb/lod/refine.h"
#include "rgb/lod/requests.h"
#include "test_meshes.h"
#include "support/set_level.h"

namespace render_test {

namespace {

rgb::Mesh refined_icosahedron() {
    rgb::Mesh mesh = icosphere(0);
    rgb::refine_uniform(mesh, 2);
    return mesh;
}

render::RenderOptions rgb_wire() {
    render::RenderOptions o;
    o.shading = render::Shading::Flat;
    o.colouring = render::Colouring::RgbType;
    o.wireframe = true;
    return o;
}

render::RenderOptions level_map() {
    render::RenderOptions o;
    o.colouring = render::Colouring::Level;
    return o;
}

render::RenderOptions limit_with_cage_and_brush() {
    render::RenderOptions o;
    o.positions = render::PositionSource::Limit;
    o.base_mesh_overlay = true;
    o.brush = render::BrushCursor{{0.0f, 0.2f, 0.75f}, 0.25f};
    return o;
}

}  // namespace

rgb::Mesh locally_refined_sphere() {
    rgb::Mesh mesh = icosphere(1);
    rgbtest::set_level(mesh, 3, rgb::Sphere{{0.3, 0.3, 0.9}, 0.6});
    return mesh;
}

std::vector<GoldenCase> golden_cases() {
    return {GoldenCase{"rgb_wire", locally_refined_sphere, rgb_wire()},
            GoldenCase{"level_legend", locally_refined_sphere, level_map()},
            GoldenCase{"limit_cage_brush", refined_icosahedron, limit_with_cage_and_brush()}};
}

render::Image render_golden(const GoldenCase& c) {
    rgb::Mesh mesh = c.mesh();
    return render::render_headless(mesh, c.options, {{256, 256}, 30.0f, 20.0f});
}

}  // namespace render_test
