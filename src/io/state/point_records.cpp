#include "io/state/point_records.h"

#include <algorithm>

#include "io/obj/number_format.h"

namespace rgbio {

namespace {

constexpr std::size_t kPointsPerLine = 8;

}  // namespace

void append_point_records(std::string& out, std::string_view name, std::span<const glm::dvec3> points,
                          const std::function<void()>& flush_if_full) {
    for (std::size_t i = 0; i < points.size(); i += kPointsPerLine) {
        out += "#rgb ";
        out += name;
        for (std::size_t k = i; k < std::min(points.size(), i + kPointsPerLine); ++k)
            for (int c = 0; c < 3; ++c) append_double(out, points[k][c]);
        out += '\n';
        flush_if_full();
    }
}

void read_point_record(StateLineReader& r, std::vector<glm::dvec3>& points, std::size_t announced, const std::string& what) {
    while (!r.at_end()) {
        glm::dvec3 p;
        for (int c = 0; c < 3; ++c) p[c] = r.number<double>();
        if (points.size() == announced) r.fail("more " + what + " than the " + std::to_string(announced) + " announced");
        points.push_back(p);
    }
}

}  // namespace rgbio
