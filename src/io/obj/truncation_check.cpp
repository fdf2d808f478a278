#include "io/obj/truncation_check.h"

#include <charconv>

#include "io/obj/text_lines.h"

namespace rgbio {

namespace {

constexpr std::string_view kHeaderStart = "# rgbsub mesh: ";
constexpr std::string_view kTagLinesStart = "; ", kTagLinesEnd = " tag lines (t)";

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

bool ends_mid_line(std::string_view text) { return !text.ends_with('\n') && !text.ends_with('\r'); }

ObjError truncated(const SavedFileHeader& header, std::size_t vertices, std::size_t faces, std::size_t line,
                   const std::string& file, const std::string& detail) {
    return ObjError(ObjProblem::Truncated, file, line,
                    "the file is truncated (cut short by an interrupted save or copy?): its rgbsub header announces " +
                        std::to_string(header.vertices) + " vertices and " + std::to_string(header.triangles) +
                        " triangles, and it holds " + std::to_string(vertices) + " vertices and " + std::to_string(faces) +
                        " faces" + detail);
}

}  // namespace

std::string tag_lines_note(std::size_t count) {
    return count == 0 ? std::string() : std::string(kTagLinesStart) + std::to_string(count) + std::string(kTagLinesEnd);
}

std::optional<SavedFileHeader> read_saved_file_header(std::string_view text) {
    if (!text.starts_with(kHeaderStart)) return std::nullopt;
    text.remove_prefix(kHeaderStart.size());
    SavedFileHeader header;
    if (!read_count(text, " vertices, ", header.vertices) || !read_count(text, " triangles", header.triangles)) return std::nullopt;
    const std::string_view rest = text.substr(0, text.find_first_of("\r\n"));
    header.state = rest.find(kSavedStateNote) != std::string_view::npos;
    const std::size_t tag_lines_end = rest.find(kTagLinesEnd);
    const std::size_t tag_lines_start = rest.substr(0, tag_lines_end).rfind(kTagLinesStart);
    if (tag_lines_end != std::string_view::npos && tag_lines_start != std::string_view::npos) {
        std::string_view count = rest.substr(tag_lines_start + kTagLinesStart.size());
        if (!read_count(count, kTagLinesEnd, header.tag_lines)) header.tag_lines = 0;
    }
    return header;
}

void check_saved_file_complete(const SavedFileHeader& header, const ObjRecords& records, std::string_view text,
                               const std::string& file) {
    const std::size_t vertices = records.positions.size(), faces = records.polygons.size();
    // The state's end line marks a complete file; without state, the newline after the last face.
    const bool state_cut = (header.state && records.state.empty()) || (!records.state.empty() && records.state.back().text != "end");
    const bool last_line_cut = records.state.empty() && ends_mid_line(text);
    const bool tags_cut = records.tags.size() < header.tag_lines;
    if (vertices >= header.vertices && faces >= header.triangles && !state_cut && !last_line_cut && !tags_cut) return;
    throw truncated(header, vertices, faces, count_body(text).last_line, file,
                    state_cut       ? "; its adaptive state (#rgb lines) is missing or stops before its end line"
                    : last_line_cut ? ", and its last line stops without a newline"
                    : tags_cut      ? "; it announces " + std::to_string(header.tag_lines) + " tag lines (t) and holds " +
                                     std::to_string(records.tags.size())
                                    : "");
}

TextEnd text_end(const ObjRecords& records, std::string_view text) {
    return {records.v_line_starts, records.f_line_starts, records.last_line, ends_mid_line(text)};
}

ObjError truncation_or(const ObjError& error, const SavedFileHeader& header, std::string_view text, const std::string& file) {
    if (error.problem() == ObjProblem::Unreadable) return error;
    const BodyCounts counts = count_body(text);
    return truncation_or(error, header, TextEnd{counts.vertices, counts.faces, counts.last_line, ends_mid_line(text)}, file);
}

ObjError truncation_or(const ObjError& error, const SavedFileHeader& header, const TextEnd& end, const std::string& file) {
    if (error.problem() == ObjProblem::Unreadable) return error;
    if (!end.cut_mid_line && end.v_lines >= header.vertices && end.f_lines >= header.triangles) return error;
    return truncated(header, end.v_lines, end.f_lines, end.last_line, file,
                     std::string(end.cut_mid_line ? ", and its last line stops without a newline" : "") +
                         "; reading it stopped" + (error.line() ? " at line " + std::to_string(error.line()) : std::string()) + ": " +
                         error.reason());
}

}  // namespace rgbio
