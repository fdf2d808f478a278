#version 330 core
uniform vec3 u_colour;
out vec4 frag_colour;

void main() { frag_colour = vec4(u_colour, 1.0); }
