#include "io/state_format.h"

#include <charconv>
#include <cmath>
#include <limits>

#include "io/number_format.h"
#include "io/obj_error.h"

namespace rgbio {

namespace {

constexpr unsigned kFormatVersion = 1;
constexpr std::size_t kIndicesPerLine = 32;

void append_number(std::string& out, std::uint64_t x) {
    out += ' ';
    out += std::to_string(x);
}

void append_vec(std::string& out, const glm::dvec3& p) {
    for (int i = 0; i < 3; ++i) append_double(out, p[i]);
}

template <class T>
void append_list(std::string& out, const char* name, const std::vector<T>& values) {
    for (std::size_t i = 0; i < values.size(); i += kIndicesPerLine) {
        out += "#rgb ";
        out += name;
        for (std::size_t k = i; k < std::min(values.size(), i + kIndicesPerLine); ++k) append_number(out, std::uint64_t(values[k]));
        out += '\n';
    }
}

// Reads the tokens of one "#rgb" line, reporting problems with its line number.
class StateLineReader {
public:
    StateLineReader(const ObjStateLine& line, const std::string& file) : rest_(line.text), line_(line.line), file_(file) {}

    std::string_view word() {
        const std::size_t b = std::min(rest_.find_first_not_of(" \t\r"), rest_.size());
        rest_.remove_prefix(b);
        const std::size_t e = std::min(rest_.find_first_of(" \t\r"), rest_.size());
        const std::string_view w = rest_.substr(0, e);
        rest_.remove_prefix(e);
        return w;
    }
    bool at_end() {
        rest_.remove_prefix(std::min(rest_.find_first_not_of(" \t\r"), rest_.size()));
        return rest_.empty();
    }
    template <class T>
    T number(T max = std::numeric_limits<T>::max()) {
        const std::string_view w = word();
        T value{};
        const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), value);
        if (w.empty() || ec != std::errc() || end != w.data() + w.size()) fail("expected a number, found '" + std::string(w.substr(0, 40)) + "'");
        if constexpr (std::is_floating_point_v<T>) {
            if (!std::isfinite(value)) fail("non-finite value");
        } else if (value > max) {
            fail("value " + std::string(w) + " is out of range");
        }
        return value;
    }
    glm::dvec3 vec() {
        glm::dvec3 p;
        for (int i = 0; i < 3; ++i) p[i] = number<double>();
        return p;
    }
    void expect_end() {
        if (!at_end()) fail("unexpected trailing values");
    }
    [[noreturn]] void fail(const std::string& reason) const {
        throw ObjError(ObjProblem::BadState, file_, line_, "rgbsub state: " + reason);
    }

private:
    std::string_view rest_;
    std::size_t line_;
    const std::string& file_;
};

}  // namespace

std::string format_state(const rgb::MeshState& state) {
    std::string out = "# rgbsub adaptive state: the #rgb lines restore the exact RGB mesh; other readers ignore them\n";
    out += "#rgb state";
    for (std::uint64_t x : {std::uint64_t(kFormatVersion), std::uint64_t(state.vertices.size()), std::uint64_t(state.faces.size()),
                            std::uint64_t(state.base_valence.size())})
        append_number(out, x);
    out += '\n';
    for (const rgb::VertexState& v : state.vertices) {
        out += "#rgb v";
        for (std::uint64_t x : {std::uint64_t(v.alive), std::uint64_t(v.level), std::uint64_t(v.boundary)}) append_number(out, x);
        append_vec(out, v.insertion_position);
        if (v.limit) append_vec(out, *v.limit);
        out += '\n';
    }
    for (const rgb::FaceState& f : state.faces) {
        out += "#rgb f";
        for (std::uint64_t x : {std::uint64_t(f.alive), std::uint64_t(f.v[0]), std::uint64_t(f.v[1]), std::uint64_t(f.v[2]),
                                std::uint64_t(f.type.colour), std::uint64_t(f.type.level), std::uint64_t(f.type.red_edge)})
            append_number(out, x);
        out += '\n';
    }
    append_list(out, "valence", state.base_valence);
    append_list(out, "free_vertices", state.free_vertices);
    append_list(out, "free_faces", state.free_faces);
    out += "#rgb end\n";
    return out;
}

rgb::MeshState parse_state(std::span<const ObjStateLine> lines, const std::string& file) {
    if (lines.empty()) throw ObjError(ObjProblem::BadState, file, 0, "rgbsub state: no #rgb lines");
    StateLineReader header(lines.front(), file);
    if (header.word() != "state") header.fail("the first #rgb line must be '#rgb state'");
    if (header.number<unsigned>() != kFormatVersion) header.fail("unsupported state format version (expected 1)");
    // Slot counts are bounded by the number of lines that describe them, checked below.
    const std::size_t vertex_slots = header.number<std::size_t>(lines.size());
    const std::size_t face_slots = header.number<std::size_t>(lines.size());
    const std::size_t base_vertices = header.number<std::size_t>(vertex_slots);
    header.expect_end();

    rgb::MeshState state;
    state.vertices.reserve(vertex_slots);
    state.faces.reserve(face_slots);
    bool ended = false;
    for (const ObjStateLine& line : lines.subspan(1)) {
        StateLineReader r(line, file);
        if (ended) r.fail("#rgb line after '#rgb end'");
        const std::string_view kind = r.word();
        if (kind == "v") {
            if (state.vertices.size() == vertex_slots) r.fail("more vertex slots than the header's " + std::to_string(vertex_slots));
            rgb::VertexState& v = state.vertices.emplace_back();
            v.alive = r.number<unsigned>(1) != 0;
            v.level = static_cast<int>(r.number<unsigned>(std::numeric_limits<std::uint8_t>::max()));
            v.boundary = r.number<unsigned>(1) != 0;
            v.insertion_position = r.vec();
            if (!r.at_end()) v.limit = r.vec();
            r.expect_end();
        } else if (kind == "f") {
            if (state.faces.size() == face_slots) r.fail("more face slots than the header's " + std::to_string(face_slots));
            rgb::FaceState& f = state.faces.emplace_back();
            f.alive = r.number<unsigned>(1) != 0;
            for (std::uint32_t& v : f.v) v = r.number<std::uint32_t>();
            f.type.colour = static_cast<rgb::Colour>(r.number<std::uint8_t>(2));
            f.type.level = r.number<std::uint8_t>();
            f.type.red_edge = r.number<std::uint8_t>(2);
            r.expect_end();
        } else if (kind == "valence" || kind == "free_vertices" || kind == "free_faces") {
            while (!r.at_end()) {
                if (kind == "valence") state.base_valence.push_back(r.number<std::uint16_t>());
                else (kind == "free_vertices" ? state.free_vertices : state.free_faces).push_back(r.number<std::uint32_t>());
            }
        } else if (kind == "end") {
            r.expect_end();
            ended = true;
        } else {
            r.fail("unknown record '" + std::string(kind.substr(0, 40)) + "'");
        }
    }
    StateLineReader last(lines.back(), file);
    if (!ended) last.fail("the state is truncated (no '#rgb end')");
    if (state.vertices.size() != vertex_slots || state.faces.size() != face_slots || state.base_valence.size() != base_vertices)
        last.fail("the header announces " + std::to_string(vertex_slots) + " vertex slots, " + std::to_string(face_slots) +
                  " face slots and " + std::to_string(base_vertices) + " base vertices, but the lines hold " +
                  std::to_string(state.vertices.size()) + ", " + std::to_string(state.faces.size()) + " and " +
                  std::to_string(state.base_valence.size()));
    return state;
}

}  // namespace rgbio
