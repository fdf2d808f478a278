#include "io/truncation_check.h"

#include <charconv>

#include "io/text_lines.h"

namespace rgbio {

namespace {

constexpr std::string_view kHeaderStart = "# rgbsub mesh: ";

// Reads "NUMBER<suffix>" off the front of text.
bool read_count(std::string_view& text, std::string_view suffix, std::size_t& count) {
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), count);
    if (ec != std::errc()) return false;
    text.remove_prefix(static_cast<std::size_t>(end - text.data()));
    if (!text.starts_with(suffix)) return false;
    text.remove_prefix(suffix.size());
    return true;
}

struct BodyCounts {
    std::size_t vertices = 0, faces = 0, last_line = 0;
};

BodyCounts count_body(std::string_view text) {
    BodyCounts counts;
    for_each_line(text, [&](std::size_t line, std::string_view content) {
        counts.last_line = line;
        if (content.starts_with("v ")) ++counts.vertices;
        if (content.starts_with("f ")) ++counts.faces;
    });
    return counts;
}

ObjError truncated(const SavedFileHeader& header, std::size_t vertices, std::size_t faces, std::size_t line,
                   const std::string& file, const std::string& detail) {
    return ObjError(ObjProblem::Truncated, file, line,
                    "the file is truncated (cut short by an interrupted save or copy?): its rgbsub header announces " +
                        std::to_string(header.vertices) + " vertices and " + std::to_string(header.triangles) +
                        " triangles, and it holds " + std::to_string(vertices) + " vertices and " + std::to_string(faces) +
                        " faces" + detail);
}

}  // namespace

std::optional<SavedFileHeader> read_saved_file_header(std::string_view text) {
    if (!text.starts_with(kHeaderStart)) return std::nullopt;
    text.remove_prefix(kHeaderStart.size());
    SavedFileHeader header;
    if (!read_count(text, " vertices, ", header.vertices) || !read_count(text, " triangles", header.triangles)) return std::nullopt;
    header.state = text.substr(0, text.find_first_of("\r\n")).find(kSavedStateNote) != std::string_view::npos;
    return header;
}

void check_saved_file_complete(const SavedFileHeader& header, const ObjRecords& records, std::string_view text,
                               const std::string& file) {
    const std::size_t vertices = records.positions.size(), faces = records.polygons.size();
    // The state's end line marks a complete file; without state, the newline after the last face.
    const bool state_cut = (header.state && records.state.empty()) || (!records.state.empty() && records.state.back().text != "end");
    const bool last_line_cut = records.state.empty() && !text.ends_with('\n') && !text.ends_with('\r');
    if (vertices >= header.vertices && faces >= header.triangles && !state_cut && !last_line_cut) return;
    throw truncated(header, vertices, faces, count_body(text).last_line, file,
                    state_cut       ? "; its adaptive state (#rgb lines) is missing or stops before its end line"
                    : last_line_cut ? ", and its last line stops without a newline"
                                    : "");
}

ObjError truncation_or(const ObjError& error, const SavedFileHeader& header, std::string_view text, const std::string& file) {
    if (error.problem() == ObjProblem::Unreadable) return error;
    const BodyCounts counts = count_body(text);
    const bool cut_mid_line = !text.ends_with('\n') && !text.ends_with('\r');
    if (!cut_mid_line && counts.vertices >= header.vertices && counts.faces >= header.triangles) return error;
    return truncated(header, counts.vertices, counts.faces, counts.last_line, file,
                     std::string(cut_mid_line ? ", and its last line stops without a newline" : "") +
                         "; reading it stopped" + (error.line() ? " at line " + std::to_string(error.line()) : std::string()) + ": " +
                         error.reason());
}

}  // namespace rgbio
