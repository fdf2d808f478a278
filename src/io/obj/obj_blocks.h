#pragma once
// Reading OBJ text in blocks of whole lines on several threads (parse_obj, obj_parser.h): what a
// block needs to know of the lines before it, and joining the blocks' records in file order. A
// block parsed with what comes before it gives the file's own line numbers and indices, so joining
// only concatenates, maps label ids, and pads colours.
#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "io/obj/obj_parser.h"

namespace rgbio {

// What the lines of a part of a file define that later lines depend on.
struct LinesBefore {
    std::size_t lines = 0, positions = 0, texcoords = 0, faces = 0;  // how many lines, v, vt and f lines
    // The values of the last usemtl, g, o and s lines, if any.
    std::optional<std::string_view> material, group, object, smoothing;

    // What these lines and then `later` ones define together.
    LinesBefore then(const LinesBefore& later) const;
};

// The text cut into at most `count` blocks of whole lines (each ends after a '\n'), in order.
std::vector<std::string_view> line_blocks(std::string_view text, std::size_t count);

// Appends the records of the block after `into`'s lines: name tables joined in order of first use,
// colours padded with "none" where one side had none.
void append_records(ObjRecords& into, const ObjRecords& block);

// parse_obj's work after its checks of the whole text: the lines read in `count` blocks on as many
// threads (one block: in one piece). The result and any error are the same for every count.
// `progress` hears of the bytes parsed.
ObjRecords parse_obj_in_blocks(std::string_view text, const std::string& file, std::size_t count,
                               const rgb::ProgressSpan& progress = {});

}  // namespace rgbio
