#include "io/state/base_colour_state.h"

#include <algorithm>

#include "io/obj/number_format.h"
#include "io/state/state_line_reader.h"

namespace rgbio {

namespace {

constexpr std::size_t kColoursPerLine = 8;

}  // namespace

void append_colour_section(std::span<const glm::dvec3> colours, std::string& out, const std::function<void()>& flush_if_full) {
    if (colours.empty()) return;
    out += "#rgb section base-colours " + std::to_string(colours.size()) + "\n";
    for (std::size_t i = 0; i < colours.size(); i += kColoursPerLine) {
        out += "#rgb " + std::string(kColourRecord);
        for (std::size_t k = i; k < std::min(colours.size(), i + kColoursPerLine); ++k)
            for (int c = 0; c < 3; ++c) append_double(out, colours[k][c]);
        out += '\n';
        flush_if_full();
    }
}

std::vector<glm::dvec3> parse_colour_section(std::span<const ObjStateLine> records, std::size_t announced, std::size_t base_vertices,
                                             const ObjStateLine& section_line, const std::string& file) {
    StateLineReader header(section_line, file);
    if (announced != base_vertices)
        header.fail("section 'base-colours' announces " + std::to_string(announced) + " colours, the base mesh has " +
                    std::to_string(base_vertices) + " vertices");
    std::vector<glm::dvec3> colours;
    colours.reserve(announced);
    for (const ObjStateLine& line : records) {
        StateLineReader r(line, file);
        r.word();  // the record's name
        while (!r.at_end()) {
            glm::dvec3 colour;
            for (int c = 0; c < 3; ++c) colour[c] = r.number<double>();
            // Bounded by the announced count, so that a forged file cannot make the list grow without end.
            if (colours.size() == announced) r.fail("more colours than the " + std::to_string(announced) + " announced");
            colours.push_back(colour);
        }
    }
    if (colours.size() != announced)
        header.fail("section 'base-colours' announces " + std::to_string(announced) + " colours but holds " + std::to_string(colours.size()));
    return colours;
}

std::optional<std::string> colour_mismatch(std::span<const glm::dvec3> colours, const ObjRecords& records) {
    const std::size_t lines = std::min(colours.size(), records.colours.size());
    std::size_t differing = 0, first = 0;
    for (std::size_t line = 0; line < lines; ++line)
        if (records.colours[line] != colours[line] && differing++ == 0) first = line;
    if (differing == 0) return std::nullopt;
    return std::to_string(differing) + " of " + std::to_string(colours.size()) + " vertex colours differ from the ones its base-colours section "
           "gives (the first on line " + std::to_string(records.position_lines[first]) + ")";
}

}  // namespace rgbio
