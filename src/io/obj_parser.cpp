#include "io/obj_parser.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>

#include "io/obj_error.h"
#include "io/obj_numbers.h"
#include "io/printable_text.h"
#include "io/text_lines.h"

namespace rgbio {

namespace {

constexpr std::string_view kWhitespace = " \t\r\f\v";

// OBJ statements for free-form geometry, display and rendering attributes: valid OBJ that a
// triangle-mesh tool has no use for (reported as ignored, unlike keywords that are not OBJ at all).
constexpr std::array<std::string_view, 28> kUnsupportedStatements = {
    "vp",    "cstype", "deg",   "bmat",     "step",     "curv",   "curv2",      "surf",      "parm",  "trim",
    "hole",  "scrv",   "sp",    "end",      "con",      "mg",     "bevel",      "c_interp",  "d_interp",
    "lod",   "usemap", "maplib", "shadow_obj", "trace_obj", "ctech", "stech", "call", "csh"};

void check_encoding(std::string_view text, const std::string& file) {
    if (text.find_first_not_of(" \t\r\n\f\v") == std::string_view::npos)
        throw ObjError(ObjProblem::Empty, file, 0, text.empty() ? "the file is empty (0 bytes)" : "the file contains only whitespace");
    const bool utf16_bom = text.size() >= 2 && ((text[0] == '\xfe' && text[1] == '\xff') || (text[0] == '\xff' && text[1] == '\xfe'));
    const std::size_t nul = text.find('\0');
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

std::string_view trim(std::string_view s) {
    const std::size_t b = s.find_first_not_of(kWhitespace);
    if (b == std::string_view::npos) return {};
    return s.substr(b, s.find_last_not_of(kWhitespace) - b + 1);
}

// Splits off the next whitespace-separated token.
std::string_view next_token(std::string_view& rest) {
    rest.remove_prefix(std::min(rest.find_first_not_of(kWhitespace), rest.size()));
    const std::size_t e = std::min(rest.find_first_of(kWhitespace), rest.size());
    std::string_view token = rest.substr(0, e);
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
    LineParser(const std::string& file, ObjRecords& out) : file_(file), out_(out) {}

    void parse(std::size_t line, std::string_view content) {
        line_ = line;
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

    void parse_vertex(std::string_view rest) {
        glm::dvec3 p;
        for (int i = 0; i < 3; ++i) {
            const std::string_view token = next_token(rest);
            if (token.empty()) fail(ObjProblem::Syntax, "vertex has " + std::to_string(i) + " coordinates, needs 3");
            p[i] = parse_real(token, "vertex coordinate");
        }
        // x y z w (rational curves' weight) is ignored; x y z r g b [a] carries a colour (MeshLab);
        // anything else after x y z (a trailing comment, say) is ignored as before.
        std::array<std::string_view, 3> colour_tokens;
        for (std::string_view& token : colour_tokens) token = next_token(rest);
        const bool has_colour = !colour_tokens[2].empty() &&
                                std::all_of(colour_tokens.begin(), colour_tokens.end(),
                                            [](std::string_view t) { return std::holds_alternative<double>(read_obj_real(t)); });
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
        ObjPolygon polygon;
        polygon.line = line_;
        std::size_t corners = 0;
        for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest), ++corners) {
            // v, v/vt, v//vn or v/vt/vn; the normal index is not read (input normals are dropped).
            const std::size_t slash = token.find('/');
            polygon.vertices.push_back(parse_index(token.substr(0, slash), token, out_.positions.size(), "face index", "vertices"));
            if (slash == std::string_view::npos) continue;
            const std::string_view after = token.substr(slash + 1);
            if (std::count(after.begin(), after.end(), '/') > 1)
                fail(ObjProblem::Syntax, "face corner " + quoted_file_text(token) + " is not v, v/vt, v//vn or v/vt/vn");
            const std::string_view texcoord = after.substr(0, after.find('/'));
            if (texcoord.empty()) continue;
            polygon.texcoords.resize(corners, kNoIndex);
            polygon.texcoords.push_back(
                parse_index(texcoord, token, out_.texcoords.size(), "texture coordinate index", "texture coordinates (vt)"));
        }
        if (polygon.vertices.size() < 3)
            fail(ObjProblem::Syntax, "face has " + std::to_string(polygon.vertices.size()) + " vertices, needs at least 3");
        if (!polygon.texcoords.empty()) polygon.texcoords.resize(corners, kNoIndex);
        polygon.material = material_.id(out_.material_names);
        polygon.group = group_.id(out_.group_names);
        polygon.object = object_.id(out_.object_names);
        polygon.smoothing_group = smoothing_group_;
        out_.polygons.push_back(std::move(polygon));
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
    std::size_t line_ = 0;
    CurrentLabel material_, group_, object_;
    std::uint32_t smoothing_group_ = 0;
};

}  // namespace

void SkippedLines::add(std::size_t line, std::string_view keyword) {
    if (count++ == 0) {
        first_line = line;
        first_keyword = keyword;
    }
}

ObjRecords parse_obj(std::string_view text, const std::string& file) {
    if (text.starts_with("\xef\xbb\xbf")) text.remove_prefix(3);  // UTF-8 byte order mark
    check_encoding(text, file);
    if (text.size() >= std::numeric_limits<std::uint32_t>::max())
        throw ObjError(ObjProblem::Unreadable, file, 0, "the file is larger than 4 GiB");
    ObjRecords records;
    LineParser parser(file, records);
    for_each_line(text, [&](std::size_t line, std::string_view content) { parser.parse(line, content); });
    return records;
}

}  // namespace rgbio
