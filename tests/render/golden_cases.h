#pragma once
// The golden images' cases: what each reviewed PNG in golden/ shows and how it is drawn. Shared by
// golden_test.cpp, which only compares, and golden_update.cpp, the separate command that rewrites
// them (target render_golden_update): running the tests never writes into the source tree.
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "render/headless.h"
#include "rgb/mesh/mesh.h"

namespace render_test {

struct GoldenCase {
    std::string name;
    std::function<rgb::Mesh()> mesh;
    render::RenderOptions options;
    friend void PrintTo(const GoldenCase& c, std::ostream* out) { *out << c.name; }
};

// Every golden image, in the order of golden/README.md.
std::vector<GoldenCase> golden_cases();
// The picture a case gives now (256x256, azimuth 30, elevation 20).
render::Image render_golden(const GoldenCase& c);
// The mesh of rgb_wire and level_legend: an icosphere refined to level 3 around one cap.
rgb::Mesh locally_refined_sphere();

}  // namespace render_test
