#include "io/state_format.h"

#include <charconv>
#include <cmath>
#include <limits>

#include "io/face_label_state.h"
#include "io/number_format.h"
#include "io/obj_error.h"

namespace rgbio {

namespace {

constexpr std::size_t kPerLine = 8;

void append_number(std::string& out, std::uint64_t x) {
    char buffer[24];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;
    out += ' ';
    out.append(buffer, end);
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
        if (w.empty()) fail("the line ends too early (is the file truncated?)");
        T value{};
        const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), value);
        if constexpr (std::is_floating_point_v<T>) {
            if (ec == std::errc::result_out_of_range || (ec == std::errc() && std::abs(value) > kMaxCoordinate))
                fail("coordinate '" + std::string(w.substr(0, 40)) + "' exceeds the supported magnitude 1e12");
        }
        if (ec != std::errc() || end != w.data() + w.size()) fail("expected a number, found '" + std::string(w.substr(0, 40)) + "'");
        if constexpr (std::is_floating_point_v<T>) {
            if (!std::isfinite(value)) fail("non-finite value");
        } else if (value > max) {
            fail("value " + std::string(w) + " is out of range (at most " + std::to_string(max) + ")");
        }
        return value;
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

void write_state(const rgb::MeshState& state, bool limit_positions, std::string& out, const std::function<void()>& flush_if_full,
                 const BaseFaceLabels& labels) {
    const std::size_t n0 = state.base_positions.size();
    out += "# rgbsub adaptive state: the #rgb lines restore the exact RGB mesh; other readers ignore them\n";
    out += "#rgb state " + std::to_string(kStateFormatVersion) + "\n";
    out += limit_positions ? "#rgb positions limit\n" : "#rgb positions displayed\n";
    out += "#rgb section base-vertices " + std::to_string(n0) + "\n";
    for (const glm::dvec3& p : state.base_positions) {
        out += "#rgb p";
        for (int i = 0; i < 3; ++i) append_double(out, p[i]);
        out += '\n';
    }
    out += "#rgb section base-faces " + std::to_string(state.base_triangles.size()) + "\n";
    for (std::size_t i = 0; i < state.base_triangles.size(); i += kPerLine) {
        out += "#rgb t";
        for (std::size_t k = i; k < std::min(state.base_triangles.size(), i + kPerLine); ++k)
            for (std::uint32_t v : state.base_triangles[k]) append_number(out, v);
        out += '\n';
        flush_if_full();
    }
    const std::size_t addresses = state.vertices.size() - std::min(n0, state.vertices.size());
    out += "#rgb section addresses " + std::to_string(addresses) + "\n";
    for (std::size_t i = n0; i < state.vertices.size(); i += kPerLine) {
        out += "#rgb a";
        for (std::size_t k = i; k < std::min(state.vertices.size(), i + kPerLine); ++k) {
            const rgb::SurfacePoint& p = state.vertices[k];
            for (std::uint64_t x : {std::uint64_t(p.face), std::uint64_t(p.a[1]), std::uint64_t(p.a[2]), std::uint64_t(p.level)})
                append_number(out, x);
        }
        out += '\n';
        flush_if_full();
    }
    append_face_label_section(labels, state.base_triangles.size(), out);
    out += "#rgb end\n";
}

std::optional<SavedState> parse_state(std::span<const ObjStateLine> lines, const std::string& file) {
    if (lines.empty()) return std::nullopt;
    StateLineReader header(lines.front(), file);
    // Another program's comments that happen to start with "#rgb": not a state at all.
    if (header.word() != "state") return std::nullopt;
    const unsigned version = header.number<unsigned>();
    if (version != kStateFormatVersion)
        header.fail("state format version " + std::to_string(version) + " (this rgbsub reads version " +
                    std::to_string(kStateFormatVersion) + ")");
    header.expect_end();

    SavedState saved;
    rgb::MeshState& state = saved.mesh;
    enum class Section { None, BaseVertices, BaseFaces, Addresses } section = Section::None;
    std::size_t expected[4] = {0, 0, 0, 0};
    bool seen[4] = {false, false, false, false};
    std::vector<rgb::SurfacePoint> addresses;
    FaceLabelSectionReader face_labels(file);
    bool ended = false;
    for (const ObjStateLine& line : lines.subspan(1)) {
        StateLineReader r(line, file);
        if (ended) r.fail("#rgb line after '#rgb end'");
        if (face_labels.take(line)) continue;
        const std::string_view kind = r.word();
        if (kind == "positions") {
            const std::string_view which = r.word();
            if (which != "displayed" && which != "limit") r.fail("positions must be 'displayed' or 'limit'");
            saved.limit_positions = which == "limit";
            r.expect_end();
        } else if (kind == "section") {
            const std::string_view name = r.word();
            if (name == "base-vertices") section = Section::BaseVertices;
            else if (name == "base-faces") section = Section::BaseFaces;
            else if (name == "addresses") section = Section::Addresses;
            else r.fail("unknown section '" + std::string(name.substr(0, 40)) + "' (written by a newer rgbsub?)");
            const auto s = static_cast<int>(section);
            if (seen[s]) r.fail("section '" + std::string(name) + "' appears twice");
            seen[s] = true;
            // Counts are bounded by what the lines can hold, so a forged count cannot exhaust memory.
            expected[s] = r.number<std::size_t>(kPerLine * lines.size());
            r.expect_end();
        } else if (kind == "p") {
            if (section != Section::BaseVertices) r.fail("a base vertex outside its section");
            glm::dvec3 p;
            for (int i = 0; i < 3; ++i) p[i] = r.number<double>();
            r.expect_end();
            state.base_positions.push_back(p);
        } else if (kind == "t") {
            if (section != Section::BaseFaces) r.fail("base faces outside their section");
            while (!r.at_end()) {
                rgb::Triangle t;
                for (std::uint32_t& v : t) v = r.number<std::uint32_t>();
                state.base_triangles.push_back(t);
            }
        } else if (kind == "a") {
            if (section != Section::Addresses) r.fail("addresses outside their section");
            while (!r.at_end()) {
                rgb::SurfacePoint p;
                p.face = r.number<std::uint32_t>();
                p.a[1] = r.number<std::uint32_t>();
                p.a[2] = r.number<std::uint32_t>();
                p.level = static_cast<int>(r.number<unsigned>(30));
                const std::uint64_t total = std::uint64_t(1) << p.level;
                if (std::uint64_t(p.a[1]) + p.a[2] > total) r.fail("an address lies outside its base face");
                p.a[0] = static_cast<std::uint32_t>(total - p.a[1] - p.a[2]);
                addresses.push_back(p);
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
    const std::size_t got[4] = {0, state.base_positions.size(), state.base_triangles.size(), addresses.size()};
    const char* names[4] = {"", "base-vertices", "base-faces", "addresses"};
    for (int s = 1; s < 4; ++s)
        if (!seen[s] || got[s] != expected[s])
            last.fail(std::string("section '") + names[s] + "' " + (seen[s] ? "announces " + std::to_string(expected[s]) +
                      " entries but holds " + std::to_string(got[s]) : std::string("is missing")));
    // A base vertex's address is its corner of a base face that uses it.
    state.vertices.assign(state.base_positions.size(), rgb::SurfacePoint{});
    std::vector<bool> placed(state.base_positions.size(), false);
    for (std::uint32_t f = 0; f < state.base_triangles.size(); ++f)
        for (int c = 0; c < 3; ++c) {
            const std::uint32_t v = state.base_triangles[f][c];
            if (v >= placed.size()) last.fail("a base face uses a missing base vertex");
            if (!placed[v]) state.vertices[v] = rgb::corner_point(f, c);
            placed[v] = true;
        }
    state.vertices.insert(state.vertices.end(), addresses.begin(), addresses.end());
    saved.labels = face_labels.finish(state.base_triangles.size(), lines.back());
    return saved;
}

}  // namespace rgbio
