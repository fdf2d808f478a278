#pragma once
// Folder io/formats: includes io/obj, io/files and the core.
// A triangle mesh as the writers of other formats take it: plain arrays, with what the adaptive mesh
// knows of each face (its level and RGB colour), so that the writers know nothing of rgb::Mesh.
// rgbio::export_mesh (io/mesh_export.h) builds one from an adaptive mesh.
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh/base_mesh.h"
#include "rgb/values/triangle_quality.h"

namespace rgbio {

struct ExportMesh {
    std::vector<glm::dvec3> positions;
    std::vector<glm::dvec3> colours;  // empty, or one per position (r, g, b in 0..1)
    std::vector<rgb::Triangle> triangles;
    std::vector<std::uint8_t> levels;       // per triangle
    std::vector<std::uint8_t> rgb_colours;  // per triangle: 0 green, 1 red, 2 blue (rgb::Colour)
};

// Per triangle, its shape at the positions written (rgb/values/triangle_quality.h).
std::vector<rgb::TriangleQuality> triangle_qualities(const ExportMesh& mesh);

// A colour channel in 0..1 as a byte (clamped, rounded).
std::uint8_t colour_byte(double channel);

// Appends the bytes of a value as this (little-endian) machine holds it: binary PLY and STL are
// little-endian.
template <class T>
void append_bytes(std::string& out, const T& value) {
    static_assert(std::endian::native == std::endian::little, "binary formats are written little-endian");
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    out.append(bytes, sizeof(T));
}

}  // namespace rgbio
