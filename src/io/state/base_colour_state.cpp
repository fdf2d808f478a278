#include "io/state/base_colour_state.h"

#include <algorithm>

#include "io/state/point_records.h"
#include "io/state/state_line_reader.h"

namespace rgbio {

void append_colour_section(std::span<const glm::dvec3> colours, std::string& out, const std::function<void()>& flush_if_full) {
    if (colours.empty()) return;
    out += "#rgb section base-colours " + std::to_string(colours.size()) + "\n";
    append_point_records(out, kColourRecord, colours, flush_if_full);
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
        read_point_record(r, colours, announced, "colours");
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
