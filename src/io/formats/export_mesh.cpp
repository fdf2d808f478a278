#include "io/formats/export_mesh.h"

#include <algorithm>
#include <cmath>

namespace rgbio {

std::vector<rgb::TriangleQuality> triangle_qualities(const ExportMesh& mesh) {
    std::vector<rgb::TriangleQuality> out;
    out.reserve(mesh.triangles.size());
    for (const rgb::Triangle& t : mesh.triangles)
        out.push_back(rgb::triangle_quality(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]));
    return out;
}

std::uint8_t colour_byte(double channel) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(channel, 0.0, 1.0) * 255.0));
}

}  // namespace rgbio
