#include "io/obj/obj_parser.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>

#include "io/obj/obj_blocks.h"
#include "io/obj/obj_error.h"
#include "io/obj/obj_numbers.h"
#include "io/obj/printable_text.h"
#include "io/obj/text_lines.h"
#include "rgb/support/parallel.h"

namespace rgbio {

namespace {

// OBJ statements for free-form geometry, display and rendering attributes: valid OBJ that a
// triangle-mesh tool has no use for (reported as ignored, unlike keywords that are not OBJ at all).
constexpr std::array<std::string_view, 28> kUnsupportedStatements = {
    "vp",    "cstype", "deg",   "bmat",     "step",     "curv",   "curv2",      "surf",      "parm",  "trim",
    "hole",  "scrv",   "sp",    "end",      "con",      "mg",     "bevel",      "c_interp",  "d_interp",
    "lod",   "usemap", "maplib", "shadow_obj", "trace_obj", "ctech", "stech", "call", "csh"};

// The offset of the first NUL byte, or npos: searched in parallel blocks, since the search reads the
// whole text (370 MB for a saved 6M-triangle file) before anything else can start.
std::size_t first_nul(std::string_view text) {
    std::vector<std::size_t> found(rgb::parallel_blocks(text.size(), std::size_t(16) << 20), std::string_view::npos);
    rgb::parallel_blocks_for(text.size(), found.size(), [&](std::size_t b, std::size_t begin, std::size_t end) {
        const std::size_t at = text.substr(begin, end - begin).find('\0');
        if (at != std::string_view::npos) found[b] = begin + at;
    });
    return *std::min_element(found.begin(), found.end());
}

void check_encoding(std::string_view text, const std::string& file) {
    if (text.find_first_not_of(" \t\r\n\f\v") == std::string_view::npos)
        throw ObjError(ObjProblem::Empty, file, 0, text.empty() ? "the file is empty (0 bytes)" : "the file contains only whitespace");
    const bool utf16_bom = text.size() >= 2 && ((text[0] == '\xfe' && text[1] == '\xff') || (text[0] == '\xff' && text[1] == '\xfe'));
    const std::size_t nul = first_nul(text);
    if (utf16_bom || nul != std::string_view::npos) {
        // UTF-16 text of ASCII content has a NUL in every other byte.
        std::size_t even_nuls = 0, odd_nuls = 0;
        const std::size_t probe = std::min<std::size_t>(text.size(), 512);
        for (std::size_t i = 0; i < probe; ++i)
            if (text[i] == '\0') ++(i % 2 ? odd_nuls : even_nuls);
        if (utf16_bom || std::max(even_nuls, odd_nuls) * 4 >= probe)
            throw ObjError(ObjProblem::Utf16, file, 0,
                           "the file is UTF-16 text; OBJ files must be ASCII/UTF-8 (re-save it as UTF-8)");
        throw ObjError(ObjProblem::Binary, file, 0,
                       "binary content (NUL byte at offset " + std::to_string(nul) + "); this is not a text OBJ file");
    }
}

// OBJ whitespace within a line, tested directly rather than searched for in a set (this runs for every byte).
bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// Digits after an optional minus sign (an OBJ index, relative when negative).
bool is_integer(std::string_view s) {
    if (s.starts_with('-')) s.remove_prefix(1);
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::string_view trim(std::string_view s) {
    std::size_t b = 0, e = s.size();
    while (b < e && is_blank(s[b])) ++b;
    while (e > b && is_blank(s[e - 1])) --e;
    return s.substr(b, e - b);
}

// Splits off the next whitespace-separated token.
std::string_view next_token(std::string_view& rest) {
    std::size_t b = 0;
    while (b < rest.size() && is_blank(rest[b])) ++b;
    std::size_t e = b;
    while (e < rest.size() && !is_blank(rest[e])) ++e;
    const std::string_view token = rest.substr(b, e - b);
    rest.remove_prefix(e);
    return token;
}

// The label a usemtl/g/o line sets, resolved to a name-table index when a face first uses it.
class CurrentLabel {
public:
    void set(std::string_view name) {
        name_ = name;
        id_ = kUnresolved;
    }
    std::uint32_t id(std::vector<std::string>& names) {
        if (id_ != kUnresolved) return id_;
        if (name_.empty()) return id_ = kNoIndex;
        const auto [it, inserted] = ids_.try_emplace(std::string(name_), static_cast<std::uint32_t>(names.size()));
        if (inserted) names.emplace_back(name_);
        return id_ = it->second;
    }

private:
    static constexpr std::uint32_t kUnresolved = kNoIndex - 1;
    std::string_view name_;
    std::uint32_t id_ = kNoIndex;
    std::map<std::string, std::uint32_t, std::less<>> ids_;
};

class LineParser {
public:
    // The lines to parse come after `before` (the whole file: after nothing); line numbers and
    // indices are the file's.
    LineParser(const std::string& file, ObjRecords& out, const LinesBefore& before) : file_(file), out_(out), before_(before) {
        if (before.material) material_.set(*before.material);
        if (before.group) group_.set(*before.group);
        if (before.object) object_.set(*before.object);
        if (before.smoothing) parse_smoothing_group(*before.smoothing);
    }

    // line_in_block: the line's number among the lines given to this parser.
    void parse(std::size_t line_in_block, std::string_view content) {
        const std::size_t line = line_ = out_.last_line = before_.lines + line_in_block;
        const bool v_line = content.starts_with("v "), f_line = content.starts_with("f ");
        out_.v_line_starts += v_line;
        out_.f_line_starts += f_line;
        if ((v_line && plain_vertex(content.substr(2))) || (f_line && plain_face(content.substr(2)))) return;
        std::string_view rest = content;
        const std::string_view keyword = next_token(rest);
        if (keyword.empty()) return;
        if (keyword == "v") parse_vertex(rest);
        else if (keyword == "vt") parse_texcoord(rest);
        else if (keyword == "f") parse_face(rest);
        else if (keyword == "vn") out_.normals.add(line, keyword);
        else if (keyword == "usemtl") material_.set(trim(rest));
        else if (keyword == "g") group_.set(trim(rest));
        else if (keyword == "o") object_.set(trim(rest));
        else if (keyword == "s") parse_smoothing_group(trim(rest));
        else if (keyword == "mtllib") parse_material_libraries(rest);
        else if (keyword == "l") ++out_.line_elements;
        else if (keyword == "p") ++out_.point_elements;
        else if (keyword == "#rgb") out_.state.push_back({trim(rest), line});
        else if (keyword == "t") out_.tags.push_back({trim(rest), line});
        else if (keyword[0] == '#') return;
        else if (std::find(kUnsupportedStatements.begin(), kUnsupportedStatements.end(), keyword) != kUnsupportedStatements.end())
            out_.unsupported.add(line, keyword);
        else out_.unknown.add(line, keyword);
    }

private:
    [[noreturn]] void fail(ObjProblem p, const std::string& reason) const { throw ObjError(p, file_, line_, reason); }

    // what: "vertex coordinate", "texture coordinate" or "vertex colour".
    double parse_real(std::string_view token, const char* what) const {
        const auto value = read_obj_real(token);
        if (std::holds_alternative<RealProblem>(value)) {
            if (std::get<RealProblem>(value) == RealProblem::Overflow)
                fail(ObjProblem::AbsurdCoordinate, std::string(what) + " " + quoted_file_text(token) + " is out of the range of a double");
            fail(ObjProblem::Syntax, std::string(what) + " " + quoted_file_text(token) + " is not a number");
        }
        const double x = std::get<double>(value);
        if (!std::isfinite(x)) fail(ObjProblem::NonFiniteCoordinate, std::string(what) + " " + quoted_file_text(token) + " is not finite");
        if (std::abs(x) > kMaxCoordinate)
            fail(ObjProblem::AbsurdCoordinate, std::string(what) + " " + quoted_file_text(token) + " exceeds the supported magnitude 1e12");
        return x;
    }

    // Most lines of a large file (all of a saved one's v and f lines) are plain: "v X Y Z" with three
    // numbers in range and nothing after them, "f A B C..." with positive indices and nothing else.
    // These read such a line in one scan, without splitting it into tokens first; for any other line
    // they read nothing and return false, and the general path reads it (and reports its problem).
    bool plain_vertex(std::string_view rest) {
        if (!out_.colours.empty()) return false;
        const char* p = rest.data();
        const char* const end = p + rest.size();
        glm::dvec3 position;
        for (int i = 0; i < 3; ++i) {
            while (p < end && is_blank(*p)) ++p;
            if (p == end || *p == '+') return false;
            const auto [stop, ec] = std::from_chars(p, end, position[i]);
            // The comparison is false for infinities and NaN too.
            if (ec != std::errc() || (stop < end && !is_blank(*stop)) || !(std::abs(position[i]) <= kMaxCoordinate)) return false;
            p = stop;
        }
        while (p < end && is_blank(*p)) ++p;
        if (p != end) return false;
        out_.positions.push_back(position);
        out_.position_lines.push_back(line_);
        return true;
    }

    bool plain_face(std::string_view rest) {
        const char* p = rest.data();
        const char* const end = p + rest.size();
        const std::size_t count = before_.positions + out_.positions.size();
        corners_.clear();
        for (;;) {
            while (p < end && is_blank(*p)) ++p;
            if (p == end) break;
            // At most 18 digits: the sum cannot overflow, and larger indices are out of range anyway.
            const char* const start = p;
            std::uint64_t index = 0;
            while (p < end && *p >= '0' && *p <= '9' && p - start < 18) index = 10 * index + static_cast<std::uint64_t>(*p++ - '0');
            if (p == start || (p < end && !is_blank(*p)) || index == 0 || index > count) return false;
            corners_.push_back(static_cast<std::uint32_t>(index - 1));
        }
        if (corners_.size() < 3) return false;
        out_.polygons.add(corners_, {}, line_, material_.id(out_.material_names), group_.id(out_.group_names), object_.id(out_.object_names),
                          smoothing_group_);
        return true;
    }

    void parse_vertex(std::string_view rest) {
        glm::dvec3 p;
        for (int i = 0; i < 3; ++i) {
            const std::string_view token = next_token(rest);
            if (token.empty()) fail(ObjProblem::Syntax, "vertex has " + std::to_string(i) + " coordinates, needs 3");
            p[i] = parse_real(token, "vertex coordinate");
        }
        // x y z w (rational curves' weight) is ignored; x y z r g b [a] carries a colour (MeshLab, alpha
        // ignored); words after x y z that are not numbers (a trailing comment, say) are ignored as
        // before. Two more numbers, or five and more, fit no form: a guess would silently misread them.
        std::array<std::string_view, 3> colour_tokens;
        std::size_t numbers = 0;
        for (std::string_view token = next_token(rest); !token.empty() && numbers < 5; token = next_token(rest)) {
            if (!std::holds_alternative<double>(read_obj_real(token))) break;
            if (numbers < colour_tokens.size()) colour_tokens[numbers] = token;
            ++numbers;
        }
        if (numbers == 2 || numbers == 5)
            fail(ObjProblem::Syntax, "vertex has " + std::string(numbers == 2 ? "5" : "8 or more") +
                                         " numbers; reads x y z, x y z w or x y z r g b [a]");
        const bool has_colour = numbers >= 3;
        if (has_colour && out_.colours.empty()) {
            out_.colours.resize(out_.positions.size(), glm::dvec3(0.0));
            out_.has_colour.resize(out_.positions.size(), 0);
        }
        if (has_colour || !out_.colours.empty()) {
            glm::dvec3 colour(0.0);
            if (has_colour)
                for (int i = 0; i < 3; ++i) colour[i] = parse_real(colour_tokens[i], "vertex colour");
            out_.colours.push_back(colour);
            out_.has_colour.push_back(has_colour);
        }
        out_.positions.push_back(p);
        out_.position_lines.push_back(line_);
    }

    void parse_texcoord(std::string_view rest) {
        glm::dvec3 uvw(0.0);
        for (int i = 0; i < 3; ++i) {
            const std::string_view token = next_token(rest);
            if (token.empty()) {
                if (i == 0) fail(ObjProblem::Syntax, "texture coordinate (vt) has no values, needs u [v [w]]");
                break;
            }
            uvw[i] = parse_real(token, "texture coordinate");
        }
        if (uvw.z != 0.0) out_.texcoord_w.add(line_, "vt");
        out_.texcoords.emplace_back(uvw.x, uvw.y);
    }

    // what: "face index" (positions) or "texture coordinate index".
    std::uint32_t parse_index(std::string_view index, std::string_view corner, std::size_t count, const char* what,
                              const char* elements) const {
        const auto resolved = read_obj_index(index, count);
        if (std::holds_alternative<std::uint32_t>(resolved)) return std::get<std::uint32_t>(resolved);
        switch (std::get<IndexProblem>(resolved)) {
            case IndexProblem::NotAnInteger:
                fail(ObjProblem::Syntax, std::string(what) + " " + quoted_file_text(corner) + " is not an integer");
            case IndexProblem::Zero:
                fail(ObjProblem::FaceIndexZero, std::string(what) + " 0 (OBJ indices start at 1)");
            case IndexProblem::OutOfRange: break;
        }
        // Only an integer (digits and a sign, safe to show as they are) can be out of range.
        fail(ObjProblem::FaceIndexOutOfRange, std::string(what) + " " + std::string(index) + " is out of range (" +
                                                  std::to_string(count) + " " + elements + " defined before this line)" +
                                                  skipped_lines_hint());
    }

    // Keywords that were not read may have been meant as vertices (`V` for `v`): say so, since
    // otherwise an index error points away from the cause.
    std::string skipped_lines_hint() const {
        if (out_.unknown.count == 0) return "";
        return "; note: " + std::to_string(out_.unknown.count) + " line" + (out_.unknown.count > 1 ? "s" : "") +
               " with an unknown keyword " + (out_.unknown.count > 1 ? "were" : "was") + " ignored before, the first on line " +
               std::to_string(out_.unknown.first_line) + " (" + quoted_file_text(out_.unknown.first_keyword) +
               "; OBJ keywords are lower case)";
    }

    void parse_face(std::string_view rest) {
        corners_.clear();
        corner_texcoords_.clear();
        std::size_t corners = 0;
        for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest), ++corners) {
            // v, v/vt, v//vn or v/vt/vn; the normal index is not read (input normals are dropped).
            // A loop, not find(): memchr's call costs more than a face corner's few bytes.
            std::size_t slash = 0;
            while (slash < token.size() && token[slash] != '/') ++slash;
            if (slash == token.size()) slash = std::string_view::npos;
            corners_.push_back(parse_index(token.substr(0, slash), token, before_.positions + out_.positions.size(), "face index", "vertices"));
            if (slash == std::string_view::npos) continue;
            const std::string_view after = token.substr(slash + 1);
            const std::size_t second = after.find('/');
            const std::string_view texcoord = after.substr(0, second);
            // The normal index is not used, but a corner that is not one of the four forms with
            // integers (1/, 1//, 1/1/, 1//x) is refused: it may be a misread or cut line.
            const bool has_normal = second != std::string_view::npos;
            if ((has_normal && !is_integer(after.substr(second + 1))) || (!has_normal && texcoord.empty()))
                fail(ObjProblem::Syntax, "face corner " + quoted_file_text(token) + " is not v, v/vt, v//vn or v/vt/vn with integers");
            if (texcoord.empty()) continue;
            corner_texcoords_.resize(corners, kNoIndex);
            corner_texcoords_.push_back(
                parse_index(texcoord, token, before_.texcoords + out_.texcoords.size(), "texture coordinate index",
                            "texture coordinates (vt)"));
        }
        if (corners_.size() < 3)
            fail(ObjProblem::Syntax, "face has " + std::to_string(corners_.size()) + " vertices, needs at least 3");
        if (!corner_texcoords_.empty()) corner_texcoords_.resize(corners, kNoIndex);
        out_.polygons.add(corners_, corner_texcoords_, line_, material_.id(out_.material_names), group_.id(out_.group_names),
                          object_.id(out_.object_names), smoothing_group_);
    }

    void parse_smoothing_group(std::string_view value) {
        std::uint32_t group = 0;
        const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), group);
        if (value != "off" && !value.empty() && (ec != std::errc() || end != value.data() + value.size()))
            fail(ObjProblem::Syntax, "smoothing group " + quoted_file_text(value) + " is neither 'off' nor a number");
        smoothing_group_ = value == "off" ? 0 : group;
    }

    void parse_material_libraries(std::string_view rest) {
        for (std::string_view name = next_token(rest); !name.empty(); name = next_token(rest))
            out_.material_libraries.emplace_back(name);
    }

    const std::string& file_;
    ObjRecords& out_;
    const LinesBefore& before_;
    std::size_t line_ = 0;
    CurrentLabel material_, group_, object_;
    std::uint32_t smoothing_group_ = 0;
    std::vector<std::uint32_t> corners_, corner_texcoords_;  // the face being read
};

}  // namespace

ObjPolygon ObjPolygons::operator[](std::size_t i) const {
    ObjPolygon p;
    const std::size_t first = start_[i], count = start_[i + 1] - first;
    p.vertices = std::span<const std::uint32_t>(vertices_).subspan(first, count);
    if (!texcoords_.empty()) {
        const auto texcoords = std::span<const std::uint32_t>(texcoords_).subspan(first, count);
        if (std::any_of(texcoords.begin(), texcoords.end(), [](std::uint32_t t) { return t != kNoIndex; })) p.texcoords = texcoords;
    }
    p.line = lines_[i];
    auto label = [i](const std::vector<std::uint32_t>& column, std::uint32_t none) { return column.empty() ? none : column[i]; };
    p.material = label(material_, kNoIndex);
    p.group = label(group_, kNoIndex);
    p.object = label(object_, kNoIndex);
    p.smoothing_group = label(smoothing_group_, 0);
    return p;
}

bool ObjPolygons::has_labels(std::uint32_t ObjPolygon::*field) const {
    // A column is filled from the first face with a label other than the default on.
    if (field == &ObjPolygon::material) return !material_.empty();
    if (field == &ObjPolygon::group) return !group_.empty();
    if (field == &ObjPolygon::object) return !object_.empty();
    return !smoothing_group_.empty();
}

void ObjPolygons::reserve(std::size_t faces, std::size_t corners) {
    start_.reserve(faces + 1);
    lines_.reserve(faces);
    vertices_.reserve(corners);
}

void ObjPolygons::add(std::span<const std::uint32_t> vertices, std::span<const std::uint32_t> texcoords, std::size_t line,
                      std::uint32_t material, std::uint32_t group, std::uint32_t object, std::uint32_t smoothing_group) {
    const std::size_t before = size();
    if (!texcoords.empty() && texcoords_.empty()) texcoords_.assign(vertices_.size(), kNoIndex);
    if (!texcoords.empty()) texcoords_.insert(texcoords_.end(), texcoords.begin(), texcoords.end());
    else if (!texcoords_.empty()) texcoords_.insert(texcoords_.end(), vertices.size(), kNoIndex);
    vertices_.insert(vertices_.end(), vertices.begin(), vertices.end());
    start_.push_back(static_cast<std::uint32_t>(vertices_.size()));
    lines_.push_back(static_cast<std::uint32_t>(line));
    auto label = [before](std::vector<std::uint32_t>& column, std::uint32_t value, std::uint32_t none) {
        if (value != none && column.empty()) column.assign(before, none);
        if (value != none || !column.empty()) column.push_back(value);
    };
    label(material_, material, kNoIndex);
    label(group_, group, kNoIndex);
    label(object_, object, kNoIndex);
    label(smoothing_group_, smoothing_group, 0);
}

void ObjPolygons::append_corners(const ObjPolygons& other) {
    const std::size_t corners_before = vertices_.size();
    vertices_.reserve(corners_before + other.vertices_.size());
    if (!other.texcoords_.empty() && texcoords_.empty()) texcoords_.assign(corners_before, kNoIndex);
    if (!other.texcoords_.empty()) texcoords_.insert(texcoords_.end(), other.texcoords_.begin(), other.texcoords_.end());
    else if (!texcoords_.empty()) texcoords_.insert(texcoords_.end(), other.vertices_.size(), kNoIndex);
    vertices_.insert(vertices_.end(), other.vertices_.begin(), other.vertices_.end());
}

void ObjPolygons::append_faces(const ObjPolygons& other, std::size_t corners_before, std::span<const std::uint32_t> material,
                               std::span<const std::uint32_t> group, std::span<const std::uint32_t> object) {
    const std::size_t before = size();
    start_.reserve(start_.size() + other.size());
    lines_.reserve(before + other.size());
    for (std::size_t i = 1; i < other.start_.size(); ++i) start_.push_back(static_cast<std::uint32_t>(corners_before + other.start_[i]));
    lines_.insert(lines_.end(), other.lines_.begin(), other.lines_.end());
    auto label = [&](std::vector<std::uint32_t>& column, const std::vector<std::uint32_t>& added, std::span<const std::uint32_t> id,
                     std::uint32_t none) {
        if (added.empty() && column.empty()) return;
        column.resize(before, none);
        if (added.empty()) column.resize(size(), none);
        for (std::uint32_t x : added) column.push_back(x == none || id.empty() ? x : id[x]);
    };
    label(material_, other.material_, material, kNoIndex);
    label(group_, other.group_, group, kNoIndex);
    label(object_, other.object_, object, kNoIndex);
    label(smoothing_group_, other.smoothing_group_, {}, 0);
}

void SkippedLines::add(std::size_t line, std::string_view keyword) {
    if (count++ == 0) {
        first_line = line;
        first_keyword = keyword;
    }
}

namespace {

// Lines between two reports of the bytes parsed: a report costs about what parsing a line does.
constexpr std::size_t kLinesPerReport = 4096;

// The lines of `text`, which come after `before`; `room` (if known): what the records are to hold
// in the end (the whole file's counts), reserved at once. Each byte parsed is added to `parsed`.
ObjRecords parse_lines(std::string_view text, const LinesBefore& before, const std::string& file, const LinesBefore& room = {},
                       rgb::ProgressCounter* parsed = nullptr) {
    ObjRecords records;
    records.positions.reserve(room.positions);
    records.position_lines.reserve(room.positions);
    records.texcoords.reserve(room.texcoords);
    records.polygons.reserve(room.faces, 3 * room.faces);  // exact for triangles
    LineParser parser(file, records, before);
    const char* reported = text.data();
    for_each_line(text, [&](std::size_t line, std::string_view content) {
        parser.parse(line, content);
        if (parsed && line % kLinesPerReport == 0) {
            parsed->add(static_cast<std::uint64_t>(content.data() - reported));
            reported = content.data();
        }
    });
    if (parsed) parsed->add(static_cast<std::uint64_t>(text.data() + text.size() - reported));
    return records;
}

// What the lines of `text` define for later ones, by the keywords LineParser reads them with.
LinesBefore summarize_lines(std::string_view text) {
    LinesBefore summary;
    for_each_line(text, [&](std::size_t, std::string_view content) {
        ++summary.lines;
        // The keyword of most lines, told at a glance (a keyword starting with '#' is none of these).
        if (content.starts_with("v ")) {
            ++summary.positions;
            return;
        }
        if (content.starts_with("f ")) {
            ++summary.faces;
            return;
        }
        if (content.starts_with('#')) return;
        std::string_view rest = content;
        const std::string_view keyword = next_token(rest);
        if (keyword == "v") ++summary.positions;
        else if (keyword == "vt") ++summary.texcoords;
        else if (keyword == "f") ++summary.faces;
        else if (keyword == "usemtl") summary.material = trim(rest);
        else if (keyword == "g") summary.group = trim(rest);
        else if (keyword == "o") summary.object = trim(rest);
        else if (keyword == "s") summary.smoothing = trim(rest);
    });
    return summary;
}

// Below this many bytes per thread, starting threads costs more than it saves.
constexpr std::size_t kBlockBytes = std::size_t(4) << 20;

// The share of parsing's time the first pass over the blocks (what each defines) takes.
constexpr double kSummarized = 0.12;

}  // namespace

ObjRecords parse_obj_in_blocks(std::string_view text, const std::string& file, std::size_t count, const rgb::ProgressSpan& progress) {
    const std::vector<std::string_view> blocks = line_blocks(text, count);
    if (blocks.size() <= 1) {
        rgb::ProgressCounter parsed(progress, text.size());
        return parse_lines(text, {}, file, {}, &parsed);
    }
    // Each block is parsed knowing what the blocks before it define; that takes a quick pass over
    // them first, itself in parallel. The first block's records, which the others join, are sized
    // for the whole file at once; the others for their own lines (grown by doubling, they would copy
    // and fault in up to twice their pages, and the slowest block holds up the join).
    std::vector<LinesBefore> summaries(blocks.size());
    rgb::parallel_blocks_for(summaries.size(), summaries.size(),
                             [&](std::size_t b, std::size_t, std::size_t) { summaries[b] = summarize_lines(blocks[b]); });
    std::vector<LinesBefore> before(blocks.size() + 1);
    for (std::size_t b = 1; b <= blocks.size(); ++b) before[b] = before[b - 1].then(summaries[b - 1]);
    progress.reach(kSummarized);
    rgb::ProgressCounter parsed(progress.part(kSummarized, 1.0), text.size());
    std::vector<ObjRecords> records_of(blocks.size());
    std::vector<std::uint8_t> failed(blocks.size(), 0);
    rgb::parallel_blocks_for(blocks.size(), blocks.size(), [&](std::size_t b, std::size_t, std::size_t) {
        try {
            records_of[b] = parse_lines(blocks[b], before[b], file, b == 0 ? before.back() : summaries[b], &parsed);
        } catch (const ObjError&) {
            if (b == 0) throw;
            failed[b] = 1;
        }
    });
    // A later block's error message may depend on lines before it (the hint about unknown keywords
    // before a bad index): the whole text, read in one piece, says it exactly as usual.
    if (std::find(failed.begin(), failed.end(), 1) != failed.end()) return parse_lines(text, {}, file);
    ObjRecords records = std::move(records_of[0]);
    for (std::size_t b = 1; b < blocks.size(); ++b) append_records(records, records_of[b]);
    progress.done();
    return records;
}

ObjRecords parse_obj(std::string_view text, const std::string& file, const rgb::ProgressSpan& progress) {
    if (text.starts_with("\xef\xbb\xbf")) text.remove_prefix(3);  // UTF-8 byte order mark
    check_encoding(text, file);
    if (text.size() >= std::numeric_limits<std::uint32_t>::max())
        throw ObjError(ObjProblem::Unreadable, file, 0, "the file is larger than 4 GiB");
    return parse_obj_in_blocks(text, file, rgb::parallel_blocks(text.size(), kBlockBytes), progress);
}

}  // namespace rgbio
