#pragma once
// The numbers `rgbsub info` prints about a mesh: counts, topology, the RGB make-up and the triangles' shape.
#include <cstddef>
#include <map>
#include <ostream>

#include "rgb/mesh/mesh.h"

namespace cli {

struct MeshSummary {
    std::size_t vertices = 0, edges = 0, faces = 0, boundary_loops = 0;
    long euler_characteristic = 0;  // V - E + F
    std::size_t green = 0, red = 0, blue = 0;
    std::map<int, std::size_t> faces_per_level;
};

MeshSummary summarize(const rgb::Mesh& mesh);
void print_summary(std::ostream& out, const MeshSummary& summary);

// The triangles' shape per level (rgb/values/triangle_quality.h): smallest angle, mean of each
// triangle's smallest angle, worst aspect ratio.
void print_quality(std::ostream& out, const rgb::Mesh& mesh);

}  // namespace cli
