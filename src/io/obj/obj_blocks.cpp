#include "io/obj/obj_blocks.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <string>

#include "rgb/support/parallel.h"

namespace rgbio {

namespace {

// Each of `later`'s names as an id in `names` (appended where new), in the order `later` lists them:
// the order of first use over both parts.
std::vector<std::uint32_t> join_names(std::vector<std::string>& names, const std::vector<std::string>& later) {
    std::map<std::string, std::uint32_t, std::less<>> ids;
    for (std::uint32_t i = 0; i < names.size(); ++i) ids.emplace(names[i], i);
    std::vector<std::uint32_t> mapped;
    mapped.reserve(later.size());
    for (const std::string& name : later) {
        const auto [it, inserted] = ids.try_emplace(name, static_cast<std::uint32_t>(names.size()));
        if (inserted) names.push_back(name);
        mapped.push_back(it->second);
    }
    return mapped;
}

void join_skipped(SkippedLines& into, const SkippedLines& later) {
    if (into.count == 0) {
        into.first_line = later.first_line;
        into.first_keyword = later.first_keyword;
    }
    into.count += later.count;
}

template <class T>
void append(std::vector<T>& into, const std::vector<T>& later) {
    // Exactly the room needed: growth by doubling would fault in up to twice the pages.
    into.reserve(into.size() + later.size());
    into.insert(into.end(), later.begin(), later.end());
}

// The block's positions and their lines and colours after `into`'s.
void append_positions(ObjRecords& into, const ObjRecords& block) {
    const std::size_t positions_before = into.positions.size();
    append(into.positions, block.positions);
    append(into.position_lines, block.position_lines);
    if (!block.colours.empty() || !into.colours.empty()) {
        // Positions without a colour line have colour 0 and has_colour 0, as parse_obj gives them.
        into.colours.resize(positions_before, glm::dvec3(0.0));
        into.has_colour.resize(positions_before, 0);
        if (block.colours.empty()) {
            into.colours.resize(into.positions.size(), glm::dvec3(0.0));
            into.has_colour.resize(into.positions.size(), 0);
        } else {
            append(into.colours, block.colours);
            append(into.has_colour, block.has_colour);
        }
    }
}

}  // namespace

LinesBefore LinesBefore::then(const LinesBefore& later) const {
    LinesBefore both = *this;
    both.lines += later.lines;
    both.positions += later.positions;
    both.texcoords += later.texcoords;
    both.faces += later.faces;
    for (auto member : {&LinesBefore::material, &LinesBefore::group, &LinesBefore::object, &LinesBefore::smoothing})
        if (later.*member) both.*member = later.*member;
    return both;
}

std::vector<std::string_view> line_blocks(std::string_view text, std::size_t count) {
    std::vector<std::string_view> blocks;
    std::size_t begin = 0;
    for (std::size_t k = 1; k <= count && begin < text.size(); ++k) {
        std::size_t end = text.size();
        if (k < count) {
            const std::size_t cut = std::max(begin, text.size() / count * k);
            const void* newline = std::memchr(text.data() + cut, '\n', text.size() - cut);
            if (newline) end = static_cast<std::size_t>(static_cast<const char*>(newline) - text.data()) + 1;
        }
        blocks.push_back(text.substr(begin, end - begin));
        begin = end;
    }
    return blocks;
}

void append_records(ObjRecords& into, const ObjRecords& block) {
    const std::vector<std::uint32_t> materials = join_names(into.material_names, block.material_names);
    const std::vector<std::uint32_t> groups = join_names(into.group_names, block.group_names);
    const std::vector<std::uint32_t> objects = join_names(into.object_names, block.object_names);
    // The polygons, and the positions and #rgb lines, are tens of MB each in a large file (about
    // 120 MB in all for a saved 6M-triangle mesh): they are copied side by side, the faces' corners
    // (about 66 MB there) on one thread, the rest on the other.
    const std::size_t corners_before = into.polygons.all_vertices().size();
    rgb::parallel_invoke([&] { into.polygons.append_corners(block.polygons); },
                         [&] {
                             into.polygons.append_faces(block.polygons, corners_before, materials, groups, objects);
                             append_positions(into, block);
                             append(into.state, block.state);
                         });
    append(into.texcoords, block.texcoords);
    append(into.tags, block.tags);
    join_skipped(into.texcoord_w, block.texcoord_w);
    append(into.material_libraries, block.material_libraries);
    into.line_elements += block.line_elements;
    into.point_elements += block.point_elements;
    join_skipped(into.normals, block.normals);
    join_skipped(into.unsupported, block.unsupported);
    join_skipped(into.unknown, block.unknown);
    into.v_line_starts += block.v_line_starts;
    into.f_line_starts += block.f_line_starts;
    into.last_line = std::max(into.last_line, block.last_line);
}

}  // namespace rgbio
