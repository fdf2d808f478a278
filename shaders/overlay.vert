#version 330 core
// Screen-space 2D overlay (the level legend) in pixel coordinates, origin at the top left.
layout(location = 0) in vec2 a_pixel;
layout(location = 1) in vec3 a_colour;

uniform vec2 u_viewport_size;

out vec3 v_colour;

void main() {
    vec2 ndc = a_pixel / u_viewport_size * 2.0 - 1.0;
    gl_Position = vec4(ndc.x, -ndc.y, 0.0, 1.0);
    v_colour = a_colour;
}
