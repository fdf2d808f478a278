#version 330 core
// Surface shading, colouring, wireframe and brush cursor in one pass: the wireframe is drawn from
// barycentric coordinates (a second glPolygonMode pass costs 3.5x on llvmpipe).
const int kMaxLevelColours = 32;
const int kColourPlain = 0;
const int kColourRgb = 1;
const int kColourLevel = 2;
const int kColourMaterial = 3;
const int kColourVertex = 4;
const int kColourChecker = 5;
const int kColourTexture = 6;
const int kColourDistance = 7;
const int kColourMatcap = 8;
const int kDistanceBands = 11;  // render/colour_map.h
// render/surface_appearance.h
const uint kNoTexture = 0xffffffffu;
const uint kUnreadableTexture = 0xfffffffeu;

in vec3 v_position;  // like u_eye and the brush, scaled by u_shading_scale (surface.vert)
in vec3 v_normal;
in vec3 v_barycentric;
flat in uint v_code;
flat in vec4 v_material_colour;  // alpha 0: no material
in vec4 v_vertex_colour;         // alpha 0: no vertex colours
in vec2 v_texcoord;
flat in uint v_texture;

uniform vec3 u_eye;
uniform mat3 u_view_rotation;  // world to camera directions (x right, y up, z towards the viewer)
uniform bool u_flat;
uniform int u_colouring;
uniform vec3 u_plain_colour;
uniform vec3 u_rgb_colours[3];
uniform vec3 u_level_colours[kMaxLevelColours];
uniform vec3 u_distance_colours[kDistanceBands];
uniform bool u_distance_measured;  // the codes carry distance bands (bits 24-31)
uniform vec3 u_checker_colours[2];
uniform float u_checker_cells;  // per unit of texture coordinate
uniform sampler2DArray u_textures;  // the materials' diffuse textures, one layer each
uniform bool u_wire;
uniform float u_wire_width;  // pixels
uniform vec3 u_wire_colour;
uniform vec3 u_back_colour;
uniform bool u_brush;
uniform vec3 u_brush_centre;
uniform float u_brush_radius;
uniform float u_brush_width;  // pixels
uniform vec3 u_brush_colour;

out vec4 frag_colour;

vec3 checker() {
    ivec2 cell = ivec2(floor(v_texcoord * u_checker_cells));
    return u_checker_colours[(cell.x + cell.y) & 1];
}

// `texel`: the face's texture at this fragment (sampled in uniform control flow, where the
// derivatives that pick its mipmap level are defined).
vec3 base_colour(vec3 texel) {
    if (u_colouring == kColourRgb) return u_rgb_colours[min(v_code & 3u, 2u)];
    if (u_colouring == kColourLevel) return u_level_colours[min(int((v_code >> 8) & 255u), kMaxLevelColours - 1)];
    if (u_colouring == kColourDistance && u_distance_measured) return u_distance_colours[min(int(v_code >> 24), kDistanceBands - 1)];
    if (u_colouring == kColourMaterial && v_material_colour.a > 0.0) return v_material_colour.rgb;
    if (u_colouring == kColourVertex && v_vertex_colour.a > 0.0) return v_vertex_colour.rgb;
    if (u_colouring == kColourChecker || (u_colouring == kColourTexture && v_texture == kUnreadableTexture)) return checker();
    if (u_colouring == kColourTexture) {
        if (v_texture != kNoTexture) return texel;
        if (v_material_colour.a > 0.0) return v_material_colour.rgb;
    }
    return u_plain_colour;
}

// The matcap: a clay sphere lit by a warm key light from the upper left, a cool fill from the lower
// right, a rim light along the silhouette and a small highlight, looked up by the normal `n` in the
// camera's frame (facing the viewer). Made here rather than read from an image, so that it needs no
// file and no texture unit.
vec3 matcap(vec3 n) {
    const vec3 kKey = normalize(vec3(-0.5, 0.6, 0.62));
    const vec3 kFill = normalize(vec3(0.7, -0.35, 0.45));
    const vec3 kClay = vec3(0.80, 0.64, 0.54);
    float key = max(dot(n, kKey), 0.0);
    float fill = max(dot(n, kFill), 0.0);
    float rim = pow(1.0 - clamp(n.z, 0.0, 1.0), 3.0);
    float highlight = pow(max(dot(n, normalize(kKey + vec3(0.0, 0.0, 1.0))), 0.0), 48.0);
    return clamp(kClay * (0.16 + 0.78 * key) + vec3(0.10, 0.13, 0.20) * fill + vec3(0.30) * rim + vec3(0.40) * highlight, 0.0, 1.0);
}

// 1 on a line of `width` pixels where `distance` (in units of its own screen derivative) is zero.
float line_coverage(float distance_in_pixels, float width) {
    return 1.0 - smoothstep(0.5 * width - 0.5, 0.5 * width + 0.5, distance_in_pixels);
}

void main() {
    vec3 texel = texture(u_textures, vec3(v_texcoord, float(v_texture))).rgb;
    vec3 normal = u_flat ? cross(dFdx(v_position), dFdy(v_position)) : v_normal;
    vec3 to_eye = normalize(u_eye - v_position);
    // Headlight, lit from both sides so open meshes show their back faces.
    float diffuse = abs(dot(normalize(normal), to_eye));
    // Back faces (inside an open mesh, seen through a hole) in a colour of their own, so that holes
    // look open.
    vec3 colour = (gl_FrontFacing ? base_colour(texel) : u_back_colour) * (0.3 + 0.7 * diffuse);
    if (u_colouring == kColourMatcap && gl_FrontFacing) {
        vec3 seen = u_view_rotation * normalize(normal);
        colour = matcap(seen.z < 0.0 ? -seen : seen);  // lit from both sides, as the headlight
    }

    if (u_wire) {
        vec3 per_pixel = max(fwidth(v_barycentric), vec3(1e-6));
        vec3 edge_pixels = v_barycentric / per_pixel;
        float d = min(edge_pixels.x, min(edge_pixels.y, edge_pixels.z));
        // Lines fade out where triangles are only a few pixels across, so that a dense wireframe
        // stays a shaded surface instead of turning solid.
        float pixels_across = 1.0 / max(per_pixel.x, max(per_pixel.y, per_pixel.z));
        colour = mix(colour, u_wire_colour, smoothstep(3.0, 10.0, pixels_across) * line_coverage(d, u_wire_width));
    }
    if (u_brush) {
        float centre_distance = distance(v_position, u_brush_centre);
        float d = abs(centre_distance - u_brush_radius) / max(fwidth(centre_distance), 1e-6);
        colour = mix(colour, u_brush_colour, line_coverage(d, u_brush_width));
    }
    frag_colour = vec4(colour, 1.0);
}
