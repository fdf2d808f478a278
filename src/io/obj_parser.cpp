#include "io/obj_parser.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>

#include "io/obj_error.h"

namespace rgbio {

namespace {

constexpr std::string_view kWhitespace = " \t\r\f\v";

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

std::string_view trim_left(std::string_view s) {
    const std::size_t b = s.find_first_not_of(kWhitespace);
    return b == std::string_view::npos ? std::string_view() : s.substr(b);
}

// Splits off the next whitespace-separated token.
std::string_view next_token(std::string_view& rest) {
    rest = trim_left(rest);
    const std::size_t e = std::min(rest.find_first_of(kWhitespace), rest.size());
    std::string_view token = rest.substr(0, e);
    rest.remove_prefix(e);
    return token;
}

std::string quoted(std::string_view token) {
    constexpr std::size_t kMaxShown = 40;
    std::string text(1, '\'');
    text += token.substr(0, kMaxShown);
    text += token.size() > kMaxShown ? "...'" : "'";
    return text;
}

class LineParser {
public:
    LineParser(const std::string& file, ObjRecords& out) : file_(file), out_(out) {}

    void parse(std::size_t line, std::string_view content) {
        line_ = line;
        std::string_view rest = content;
        const std::string_view keyword = next_token(rest);
        if (keyword == "v") parse_vertex(rest);
        else if (keyword == "f") parse_face(rest);
        else if (keyword == "l") ++out_.line_elements;
        else if (keyword == "p") ++out_.point_elements;
        else if (keyword == "#rgb") out_.state.push_back({trim_left(rest), line});
    }

private:
    [[noreturn]] void fail(ObjProblem p, const std::string& reason) const { throw ObjError(p, file_, line_, reason); }

    double parse_coordinate(std::string_view token) const {
        // from_chars rejects the leading '+' that OBJ exporters sometimes write.
        std::string_view digits = token;
        if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-' && digits[1] != '+') digits.remove_prefix(1);
        double value = 0.0;
        const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
        if (ec == std::errc::result_out_of_range)
            fail(ObjProblem::AbsurdCoordinate, "coordinate " + quoted(token) + " is out of the range of a double");
        if (ec != std::errc() || end != digits.data() + digits.size())
            fail(ObjProblem::Syntax, "vertex coordinate " + quoted(token) + " is not a number");
        if (!std::isfinite(value))
            fail(ObjProblem::NonFiniteCoordinate, "vertex coordinate " + quoted(token) + " is not finite");
        if (std::abs(value) > kMaxCoordinate)
            fail(ObjProblem::AbsurdCoordinate, "vertex coordinate " + quoted(token) + " exceeds the supported magnitude 1e12");
        return value;
    }

    void parse_vertex(std::string_view rest) {
        glm::dvec3 p;
        for (int i = 0; i < 3; ++i) {
            const std::string_view token = next_token(rest);
            if (token.empty()) fail(ObjProblem::Syntax, "vertex has " + std::to_string(i) + " coordinates, needs 3");
            p[i] = parse_coordinate(token);
        }
        // Further values (w, or vertex colours) are allowed and ignored.
        out_.positions.push_back(p);
        out_.position_lines.push_back(line_);
    }

    std::uint32_t parse_index(std::string_view token) const {
        // v, v/vt, v//vn or v/vt/vn: only the position index matters.
        const std::string_view index = token.substr(0, token.find('/'));
        long long value = 0;
        const auto [end, ec] = std::from_chars(index.data(), index.data() + index.size(), value);
        const long long count = static_cast<long long>(out_.positions.size());
        if (ec == std::errc::result_out_of_range)
            fail(ObjProblem::FaceIndexOutOfRange, "face index " + quoted(index) + " is out of range (" + std::to_string(count) + " vertices so far)");
        if (ec != std::errc() || end != index.data() + index.size())
            fail(ObjProblem::Syntax, "face index " + quoted(token) + " is not an integer");
        if (value == 0) fail(ObjProblem::FaceIndexZero, "face index 0 (OBJ vertex indices start at 1)");
        const long long resolved = value > 0 ? value - 1 : count + value;
        if (resolved < 0 || resolved >= count)
            fail(ObjProblem::FaceIndexOutOfRange, "face index " + std::to_string(value) + " is out of range (" +
                                                      std::to_string(count) + " vertices defined before this line)");
        return static_cast<std::uint32_t>(resolved);
    }

    void parse_face(std::string_view rest) {
        ObjPolygon polygon;
        polygon.line = line_;
        for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest))
            polygon.vertices.push_back(parse_index(token));
        if (polygon.vertices.size() < 3)
            fail(ObjProblem::Syntax, "face has " + std::to_string(polygon.vertices.size()) + " vertices, needs at least 3");
        out_.polygons.push_back(std::move(polygon));
    }

    const std::string& file_;
    ObjRecords& out_;
    std::size_t line_ = 0;
};

}  // namespace

ObjRecords parse_obj(std::string_view text, const std::string& file) {
    if (text.starts_with("\xef\xbb\xbf")) text.remove_prefix(3);  // UTF-8 byte order mark
    check_encoding(text, file);
    if (text.size() >= std::numeric_limits<std::uint32_t>::max())
        throw ObjError(ObjProblem::Unreadable, file, 0, "the file is larger than 4 GiB");
    ObjRecords records;
    LineParser parser(file, records);
    std::size_t line = 1;
    while (!text.empty()) {
        const std::size_t end = std::min(text.find('\n'), text.size());
        parser.parse(line, text.substr(0, end));
        text.remove_prefix(std::min(end + 1, text.size()));
        ++line;
    }
    return records;
}

}  // namespace rgbio
