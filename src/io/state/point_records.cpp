#include "io/state/point_records.h"

#include <algorithm>
#include <vector>

#include "io/obj/number_format.h"
#include "rgb/support/parallel.h"

namespace rgbio {

namespace {

constexpr std::size_t kPointsPerLine = 8;
// The records are formatted on all cores a batch at a time, each block of lines into its own text,
// then appended in order: the same bytes as one loop, since a line depends only on its points. A
// block is about 240 KB of text, a batch 16 blocks (the memory it takes beside the file's buffer).
// Formatting the shortest round-trip digits (std::to_chars) is most of the cost of a large detail
// section: a million points (60 MB) took about 0.55 s in one loop (docs/benchmarks.md).
constexpr std::size_t kLinesPerBlock = 512;
constexpr std::size_t kBlocksPerBatch = 16;

void append_lines(std::string& out, std::string_view name, std::span<const glm::dvec3> points, std::size_t first_line,
                  std::size_t end_line) {
    for (std::size_t line = first_line; line < end_line; ++line) {
        const std::size_t i = line * kPointsPerLine;
        out += "#rgb ";
        out += name;
        for (std::size_t k = i; k < std::min(points.size(), i + kPointsPerLine); ++k)
            for (int c = 0; c < 3; ++c) append_double(out, points[k][c]);
        out += '\n';
    }
}

}  // namespace

void append_point_records(std::string& out, std::string_view name, std::span<const glm::dvec3> points,
                          const std::function<void()>& flush_if_full) {
    const std::size_t lines = (points.size() + kPointsPerLine - 1) / kPointsPerLine;
    std::vector<std::string> blocks;
    for (std::size_t batch = 0; batch < lines; batch += kLinesPerBlock * kBlocksPerBatch) {
        const std::size_t batch_end = std::min(lines, batch + kLinesPerBlock * kBlocksPerBatch);
        blocks.assign((batch_end - batch + kLinesPerBlock - 1) / kLinesPerBlock, std::string());
        rgb::parallel_for(blocks.size(), 1, [&](std::size_t begin, std::size_t end) {
            for (std::size_t b = begin; b < end; ++b) {
                const std::size_t first = batch + b * kLinesPerBlock;
                append_lines(blocks[b], name, points, first, std::min(batch_end, first + kLinesPerBlock));
            }
        });
        for (const std::string& block : blocks) {
            out += block;
            flush_if_full();
        }
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
