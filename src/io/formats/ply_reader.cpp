#include "io/formats/ply_reader.h"

#include <algorithm>
#include <bit>
#include <optional>
#include <charconv>
#include <cstring>

#include "io/files/file_text.h"
#include "io/formats/binary_value.h"
#include "io/obj/obj_error.h"

namespace rgbio {

namespace {

enum class PlyType : std::uint8_t { Int8, Uint8, Int16, Uint16, Int32, Uint32, Float32, Float64 };
enum class PlyEncoding : std::uint8_t { Ascii, Little, Big };

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::Float32;
    bool list = false;
    PlyType count_type = PlyType::Uint8;
};

struct PlyElement {
    std::string name;
    std::size_t count = 0;
    std::vector<PlyProperty> properties;
};

std::size_t size_of(PlyType t) {
    switch (t) {
        case PlyType::Int8: case PlyType::Uint8: return 1;
        case PlyType::Int16: case PlyType::Uint16: return 2;
        case PlyType::Int32: case PlyType::Uint32: case PlyType::Float32: return 4;
        case PlyType::Float64: return 8;
    }
    return 1;
}

// The largest value of an integer type, by which a colour of that type is scaled to 0-1.
double colour_scale(PlyType t) {
    switch (t) {
        case PlyType::Int8: return 127.0;
        case PlyType::Uint8: return 255.0;
        case PlyType::Int16: return 32767.0;
        case PlyType::Uint16: return 65535.0;
        case PlyType::Int32: return 2147483647.0;
        case PlyType::Uint32: return 4294967295.0;
        case PlyType::Float32: case PlyType::Float64: return 1.0;
    }
    return 1.0;
}

// The body, value by value, in either encoding.
class PlyBody {
public:
    PlyBody(std::string_view bytes, PlyEncoding encoding, const std::string& path) : bytes_(bytes), encoding_(encoding), path_(path) {}

    [[noreturn]] void fail(const std::string& reason) const { throw ObjError(ObjProblem::Malformed, path_, 0, reason); }
    void set_place(const PlyElement& element, std::size_t i) {
        element_ = &element;
        index_ = i;
    }
    std::size_t remaining() const { return bytes_.size() - at_; }

    double next(PlyType type) {
        if (encoding_ == PlyEncoding::Ascii) return next_text();
        const std::size_t size = size_of(type);
        if (remaining() < size) fail("the file ends inside " + place());
        unsigned char raw[8];
        std::memcpy(raw, bytes_.data() + at_, size);
        at_ += size;
        if ((encoding_ == PlyEncoding::Big) == (std::endian::native == std::endian::little)) std::reverse(raw, raw + size);
        switch (type) {
            case PlyType::Int8: return binary_value<std::int8_t>(raw);
            case PlyType::Uint8: return binary_value<std::uint8_t>(raw);
            case PlyType::Int16: return binary_value<std::int16_t>(raw);
            case PlyType::Uint16: return binary_value<std::uint16_t>(raw);
            case PlyType::Int32: return binary_value<std::int32_t>(raw);
            case PlyType::Uint32: return binary_value<std::uint32_t>(raw);
            case PlyType::Float32: return binary_value<float>(raw);
            case PlyType::Float64: return binary_value<double>(raw);
        }
        return 0.0;
    }
    // A list's length, checked against what is left of the file (each entry takes a byte at least).
    std::size_t list_size(PlyType count_type) {
        const double n = next(count_type);
        if (n < 0 || n > static_cast<double>(remaining())) fail("a list of " + place() + " is longer than the file");
        return static_cast<std::size_t>(n);
    }
    std::string place() const {
        return element_ ? "element '" + element_->name + "' " + std::to_string(index_ + 1) + " of " + std::to_string(element_->count) : "the body";
    }

private:
    double next_text() {
        while (at_ < bytes_.size() && (bytes_[at_] == ' ' || bytes_[at_] == '\t' || bytes_[at_] == '\n' || bytes_[at_] == '\r')) ++at_;
        if (at_ == bytes_.size()) fail("the file ends inside " + place());
        double value = 0.0;
        const char* begin = bytes_.data() + at_;
        const auto [end, error] = std::from_chars(begin, bytes_.data() + bytes_.size(), value);
        if (error != std::errc() || (end < bytes_.data() + bytes_.size() && *end != ' ' && *end != '\t' && *end != '\n' && *end != '\r'))
            fail("a value of " + place() + " is not a number");
        at_ = static_cast<std::size_t>(end - bytes_.data());
        return value;
    }
    std::string_view bytes_;
    PlyEncoding encoding_;
    const std::string& path_;
    std::size_t at_ = 0;
    const PlyElement* element_ = nullptr;
    std::size_t index_ = 0;
};

std::optional<PlyType> parse_type(std::string_view word) {
    static constexpr std::pair<std::string_view, PlyType> kNames[] = {
        {"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::Uint8},     {"uint8", PlyType::Uint8},
        {"short", PlyType::Int16},    {"int16", PlyType::Int16},     {"ushort", PlyType::Uint16},   {"uint16", PlyType::Uint16},
        {"int", PlyType::Int32},      {"int32", PlyType::Int32},     {"uint", PlyType::Uint32},     {"uint32", PlyType::Uint32},
        {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},  {"float64", PlyType::Float64}};
    for (const auto& [name, type] : kNames)
        if (word == name) return type;
    return std::nullopt;
}

std::vector<std::string_view> header_words(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
    return out;
}

struct PlyHeader {
    PlyEncoding encoding = PlyEncoding::Ascii;
    std::vector<PlyElement> elements;
    std::size_t body = 0;  // where the body starts
    std::size_t unknown_lines = 0, first_unknown = 0;  // header lines that are no PLY keyword
};

PlyHeader parse_header(std::string_view text, const std::string& path) {
    const auto fail = [&](std::size_t line, const std::string& reason) { throw ObjError(ObjProblem::Malformed, path, line, reason); };
    if (!text.starts_with("ply\n") && !text.starts_with("ply\r\n")) fail(1, "not a PLY file: it does not start with the line 'ply'");
    PlyHeader header;
    bool format = false;
    std::size_t at = 0, line = 0;
    while (true) {
        const std::size_t end = text.find('\n', at);
        if (end == std::string_view::npos) fail(line + 1, "the header has no end_header line");
        ++line;
        const std::vector<std::string_view> w = header_words(text.substr(at, end - at));
        at = end + 1;
        if (w.empty() || w[0] == "comment" || w[0] == "obj_info" || (line == 1 && w[0] == "ply")) continue;
        if (w[0] == "end_header") break;
        if (w[0] == "format") {
            if (w.size() < 2) fail(line, "the format line names no format");
            if (w[1] == "ascii") header.encoding = PlyEncoding::Ascii;
            else if (w[1] == "binary_little_endian") header.encoding = PlyEncoding::Little;
            else if (w[1] == "binary_big_endian") header.encoding = PlyEncoding::Big;
            else fail(line, "unknown PLY format '" + std::string(w[1]) + "'");
            format = true;
        } else if (w[0] == "element") {
            std::size_t count = 0;
            if (w.size() != 3 || std::from_chars(w[2].data(), w[2].data() + w[2].size(), count).ec != std::errc())
                fail(line, "an element line must read 'element NAME COUNT'");
            header.elements.push_back({std::string(w[1]), count, {}});
        } else if (w[0] == "property") {
            if (header.elements.empty()) fail(line, "a property before any element");
            PlyProperty property;
            const bool list = w.size() == 5 && w[1] == "list";
            const std::optional<PlyType> type = parse_type(w.size() > 1 ? w[list ? 3 : 1] : "");
            const std::optional<PlyType> count_type = list ? parse_type(w[2]) : PlyType::Uint8;
            if ((w.size() != 3 && !list) || !type || !count_type) fail(line, "a property line must read 'property TYPE NAME' or 'property list TYPE TYPE NAME'");
            header.elements.back().properties.push_back({std::string(w.back()), *type, list, *count_type});
        } else {
            // Some writers put free text in the header (Wuson.ply: "Created by ..."): skipped, said.
            if (header.unknown_lines++ == 0) header.first_unknown = line;
        }
    }
    if (!format) fail(1, "the header has no format line");
    header.body = at;
    return header;
}

// Where each property of the vertex element goes: a coordinate, a colour or UV component, or nowhere.
enum class Slot : std::uint8_t { X, Y, Z, Red, Green, Blue, U, V, Normal, Other };

Slot vertex_slot(const std::string& name) {
    if (name == "x") return Slot::X;
    if (name == "y") return Slot::Y;
    if (name == "z") return Slot::Z;
    if (name == "red" || name == "diffuse_red") return Slot::Red;
    if (name == "green" || name == "diffuse_green") return Slot::Green;
    if (name == "blue" || name == "diffuse_blue") return Slot::Blue;
    if (name == "s" || name == "u" || name == "texture_u" || name == "texture_s") return Slot::U;
    if (name == "t" || name == "v" || name == "texture_v" || name == "texture_t") return Slot::V;
    if (name == "nx" || name == "ny" || name == "nz") return Slot::Normal;
    return Slot::Other;
}

void read_vertices(PlyBody& body, const PlyElement& element, ForeignMesh& out) {
    std::vector<Slot> slots;
    bool colour = false, uv = false, normals = false;
    int coordinates = 0;
    for (const PlyProperty& p : element.properties) {
        slots.push_back(p.list ? Slot::Other : vertex_slot(p.name));
        coordinates += slots.back() <= Slot::Z;
        colour |= slots.back() == Slot::Red;
        uv |= slots.back() == Slot::U;
        normals |= slots.back() == Slot::Normal;
    }
    if (coordinates != 3) body.fail("the vertex element needs the properties x, y and z");
    if (element.count > body.remaining()) body.fail("the vertex element's count (" + std::to_string(element.count) + ") is beyond the file's size");
    out.positions.resize(element.count);
    if (colour) out.colours.resize(element.count, glm::dvec3(0.0));
    if (uv) out.vertex_uvs.resize(element.count, glm::dvec2(0.0));
    std::size_t others = 0;
    for (std::size_t i = 0; i < element.count; ++i) {
        body.set_place(element, i);
        for (std::size_t k = 0; k < slots.size(); ++k) {
            const PlyProperty& p = element.properties[k];
            if (p.list) {
                for (std::size_t j = body.list_size(p.count_type); j > 0; --j) body.next(p.type);
                continue;
            }
            const double value = body.next(p.type);
            switch (slots[k]) {
                case Slot::X: case Slot::Y: case Slot::Z: out.positions[i][static_cast<int>(slots[k])] = value; break;
                case Slot::Red: case Slot::Green: case Slot::Blue:
                    out.colours[i][static_cast<int>(slots[k]) - static_cast<int>(Slot::Red)] = value / colour_scale(p.type);
                    break;
                case Slot::U: out.vertex_uvs[i].x = value; break;
                case Slot::V: out.vertex_uvs[i].y = value; break;
                case Slot::Normal: break;
                case Slot::Other: others += i == 0; break;
            }
        }
    }
    if (normals) out.dropped.push_back(std::string("vertex normals (nx, ny, nz)") + kNormalsRecomputed);
    note_dropped(out, others, "other vertex properties (alpha, quality, ...)");
}

void read_faces(PlyBody& body, const PlyElement& element, ForeignMesh& out) {
    std::size_t others = 0;
    int indices = -1, texcoords = -1;
    for (std::size_t k = 0; k < element.properties.size(); ++k) {
        const PlyProperty& p = element.properties[k];
        if (p.list && (p.name == "vertex_indices" || p.name == "vertex_index")) indices = static_cast<int>(k);
        else if (p.list && p.name == "texcoord") texcoords = static_cast<int>(k);
        else ++others;
    }
    if (indices < 0) body.fail("the face element has no vertex_indices list");
    if (element.count > body.remaining()) body.fail("the face element's count (" + std::to_string(element.count) + ") is beyond the file's size");
    out.corners.reserve(3 * element.count);
    out.face_start.reserve(element.count + 1);
    std::vector<glm::dvec2> uvs;
    for (std::size_t i = 0; i < element.count; ++i) {
        body.set_place(element, i);
        uvs.clear();
        for (std::size_t k = 0; k < element.properties.size(); ++k) {
            const PlyProperty& p = element.properties[k];
            if (!p.list) {
                body.next(p.type);
                continue;
            }
            const std::size_t n = body.list_size(p.count_type);
            for (std::size_t j = 0; j < n; ++j) {
                const double value = body.next(p.type);
                if (static_cast<int>(k) == indices) {
                    if (value < 0 || value >= static_cast<double>(out.positions.size()))
                        body.fail(body.place() + " names vertex " + std::to_string(static_cast<long long>(value)) + " of " +
                                  std::to_string(out.positions.size()));
                    out.corners.push_back(static_cast<std::uint32_t>(value));
                } else if (static_cast<int>(k) == texcoords) {
                    if (j % 2 == 0) uvs.emplace_back(value, 0.0);
                    else uvs.back().y = value;
                }
            }
        }
        const std::size_t corners = out.corners.size() - out.face_start.back();
        if (texcoords >= 0) {
            // A face whose texcoord list does not give one UV per corner gets (0, 0) at each.
            uvs.resize(corners, glm::dvec2(0.0));
            out.corner_uvs.insert(out.corner_uvs.end(), uvs.begin(), uvs.begin() + static_cast<std::ptrdiff_t>(corners));
        }
        out.face_start.push_back(static_cast<std::uint32_t>(out.corners.size()));
    }
    note_dropped(out, others, "other face properties");
}

}  // namespace

ForeignMesh read_ply_mesh(const std::string& path) {
    const FileText text = read_file_text(path);
    const PlyHeader header = parse_header(text.view(), path);
    PlyBody body(text.view().substr(header.body), header.encoding, path);
    ForeignMesh out;
    if (header.unknown_lines > 0)
        out.warnings.push_back("ignored " + std::to_string(header.unknown_lines) + " header lines that are no PLY keyword (the first is line " +
                               std::to_string(header.first_unknown) + ")");
    bool vertices = false;
    for (const PlyElement& element : header.elements) {
        if (element.name == "vertex") {
            read_vertices(body, element, out);
            vertices = true;
        } else if (element.name == "face") {
            if (!vertices) body.fail("the face element comes before the vertex element");
            read_faces(body, element, out);
        } else {
            // Skipped value by value: in a binary file its lists decide where the next element starts.
            for (std::size_t i = 0; i < element.count && !element.properties.empty(); ++i) {
                body.set_place(element, i);
                for (const PlyProperty& p : element.properties) {
                    for (std::size_t j = p.list ? body.list_size(p.count_type) : 1; j > 0; --j) body.next(p.type);
                }
            }
            note_dropped(out, element.count, "elements '" + element.name + "'");
        }
    }
    text.check_not_shrunk();
    return out;
}

}  // namespace rgbio
