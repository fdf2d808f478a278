#version 330 core
// One vertex per face corner (face slot f owns vertices 3f..3f+2), so the corner index, and with it
// the barycentric coordinate used by the wireframe, follows from gl_VertexID alone.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in uint a_code;  // bits 0-1: RGB colour, bits 8-15: face level, 24-31: distance band
// The file's look (render/surface_appearance.h); alpha 0: the file gives no colour there.
layout(location = 3) in vec4 a_material_colour;
layout(location = 4) in vec4 a_vertex_colour;
layout(location = 5) in vec2 a_texcoord;
layout(location = 6) in uint a_texture;  // a layer of u_textures, or kNoTexture / kUnreadableTexture

uniform mat4 u_view_projection;
uniform float u_shading_scale;  // a power of two that brings the scene near unit size (renderer.cpp)

out vec3 v_position;
out vec3 v_normal;
out vec3 v_barycentric;
flat out uint v_code;
flat out vec4 v_material_colour;
out vec4 v_vertex_colour;
out vec2 v_texcoord;
flat out uint v_texture;

void main() {
    int corner = gl_VertexID % 3;
    v_barycentric = vec3(corner == 0, corner == 1, corner == 2);
    v_position = a_position * u_shading_scale;
    v_normal = a_normal;
    v_code = a_code;
    v_material_colour = a_material_colour;
    v_vertex_colour = a_vertex_colour;
    v_texcoord = a_texcoord;
    v_texture = a_texture;
    gl_Position = u_view_projection * vec4(a_position, 1.0);
}
