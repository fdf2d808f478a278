#include "support/obj_reader.h"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rgbtest {
namespace {

[[noreturn]] void fail(const std::string& path, int line, const std::string& problem) {
    throw std::runtime_error(path + ":" + std::to_string(line) + ": " + problem);
}

}  // namespace

TestMesh read_obj(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot open");
    TestMesh mesh{path, {}, {}};
    std::string text;
    int line = 0;
    while (std::getline(in, text)) {
        ++line;
        std::istringstream fields(text);
        std::string tag;
        fields >> tag;
        if (tag == "v") {
            glm::dvec3 p;
            if (!(fields >> p.x >> p.y >> p.z)) fail(path, line, "vertex needs three numbers");
            mesh.positions.push_back(p);
        } else if (tag == "f") {
            std::vector<long> corners;
            std::string corner;
            while (fields >> corner) {
                long index = 0;
                const char* end = corner.data() + std::min(corner.find('/'), corner.size());
                if (std::from_chars(corner.data(), end, index).ptr != end) fail(path, line, "bad index '" + corner + "'");
                corners.push_back(index);
            }
            if (corners.size() != 3) fail(path, line, "only triangles are supported");
            rgb::Triangle t;
            for (int i = 0; i < 3; ++i) {
                const long count = static_cast<long>(mesh.positions.size());
                const long index = corners[i] < 0 ? count + corners[i] : corners[i] - 1;
                if (index < 0 || index >= count) fail(path, line, "vertex index out of range");
                t[i] = static_cast<std::uint32_t>(index);
            }
            mesh.triangles.push_back(t);
        }
    }
    return mesh;
}

}  // namespace rgbtest
