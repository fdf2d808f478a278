#version 330 core
// Lines drawn over the surface (the base mesh overlay), pulled slightly towards the viewer so that
// they win the depth test where they lie on the surface.
layout(location = 0) in vec3 a_position;

uniform mat4 u_view_projection;
uniform float u_depth_bias;

void main() {
    gl_Position = u_view_projection * vec4(a_position, 1.0);
    gl_Position.z -= u_depth_bias * gl_Position.w;
}
