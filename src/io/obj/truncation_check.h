#pragma once
// Files rgbsub saves start with "# rgbsub mesh: N vertices, M triangles" (mesh_file.cpp), followed
// on that line by a count of their t lines when they have any (tag_lines_note) and by
// kSavedStateNote when #rgb state lines end the file, end every line with a newline, and end their
// state with "#rgb end". A file with that header that breaks
// those promises was cut short (an interrupted save or copy), and saying so names the real cause
// better than whatever the cut-off content looks like (a bow-tie, an out-of-range value...).
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "io/obj/obj_error.h"
#include "io/obj/obj_parser.h"

namespace rgbio {

inline constexpr std::string_view kSavedStateNote = "; adaptive state: #rgb lines at the end";

struct SavedFileHeader {
    std::size_t vertices = 0, triangles = 0;
    std::size_t tag_lines = 0;  // t lines (crease_tags.h) announced: a file cut just before them looks whole otherwise
    bool state = false;         // the header announces #rgb state lines
};

// What the header says of `count` t lines: "; N tag lines (t)", nothing for none (so that files
// without tags stay as they were).
std::string tag_lines_note(std::size_t count);

// The header on the first line, if the text has one.
std::optional<SavedFileHeader> read_saved_file_header(std::string_view text);

// Throws ObjError(Truncated) when the parsed file holds fewer vertices, faces or t lines than its
// header announces, its announced state is missing or lacks its end line, or (without state) its
// last line lacks its newline.
void check_saved_file_complete(const SavedFileHeader& header, const ObjRecords& records, std::string_view text,
                               const std::string& file);

// What truncation_or needs to know of a text: how many lines start "v " and "f ", the number of its
// last line, and whether it ends without a line break.
struct TextEnd {
    std::size_t v_lines = 0, f_lines = 0, last_line = 0;
    bool cut_mid_line = false;
};
// The same for records parsed from `text` (which counted its lines on the way).
TextEnd text_end(const ObjRecords& records, std::string_view text);

// For an error found while reading a file with the header: ObjError(Truncated) (naming the
// original reason) when the text ends without a newline or holds fewer v/f lines than announced;
// otherwise the error itself.
ObjError truncation_or(const ObjError& error, const SavedFileHeader& header, std::string_view text, const std::string& file);
// The same, once the text is gone (a loaded saved file's text is released before its mesh is built).
ObjError truncation_or(const ObjError& error, const SavedFileHeader& header, const TextEnd& end, const std::string& file);

}  // namespace rgbio
