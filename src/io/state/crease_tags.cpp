#include "io/state/crease_tags.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <iterator>
#include <unordered_set>

#include "io/obj/number_format.h"
#include "io/obj/obj_error.h"
#include "io/obj/printable_text.h"
#include "rgb/mesh/sharp_edges.h"
#include "rgb/values/loop_geometry.h"

namespace rgbio {

namespace {

std::vector<std::string_view> words(std::string_view text) {
    std::vector<std::string_view> out;
    constexpr std::string_view space = " \t\r\f\v";
    while (true) {
        const std::size_t b = text.find_first_not_of(space);
        if (b == std::string_view::npos) return out;
        text.remove_prefix(b);
        const std::size_t e = std::min(text.find_first_of(space), text.size());
        out.push_back(text.substr(0, e));
        text.remove_prefix(e);
    }
}

template <class T>
bool read_number(std::string_view w, T& value) {
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), value);
    return ec == std::errc() && end == w.data() + w.size();
}

std::string shown(std::string_view w) { return quoted_file_text(w.substr(0, 40)); }

// Sharpness on OpenSubdiv's scale as rgbsub keeps it: an integer, 10 and above infinite.
int integer_sharpness(double s, const std::function<void(const std::string&)>& fail) {
    if (!std::isfinite(s) || s < 0.0) fail("sharpness must be a number from 0 to 10 (10: infinitely sharp)");
    if (s >= rgb::kInfiniteSharpness) return rgb::kInfiniteSharpness;
    if (s != std::floor(s))
        fail("fractional sharpness " + std::to_string(s) +
             " is not supported: rgbsub refines with integer sharpness 0-10 (10: infinitely sharp), so that every level "
             "is exact; round it in the file");
    return static_cast<int>(s);
}

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) { return (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b); }

}  // namespace

FileTags parse_tag_lines(std::span<const ObjStateLine> lines, std::size_t file_vertices, const std::string& file) {
    FileTags tags;
    for (const ObjStateLine& line : lines) {
        auto fail = [&](const std::string& reason) {
            throw ObjError(ObjProblem::BadTag, file, line.line, "tag line (t): " + reason);
        };
        const std::vector<std::string_view> w = words(line.text);
        if (w.empty()) fail("no tag name");
        const std::string_view name = w[0];
        // "INTS/FLOATS/STRINGS": how many values of each kind follow.
        std::size_t counts[3] = {0, 0, 0};
        if (w.size() < 2) fail("expected the value counts INTS/FLOATS/STRINGS after the name " + shown(name));
        {
            std::string_view c = w[1];
            for (int k = 0; k < 3; ++k) {
                const std::size_t slash = k < 2 ? c.find('/') : c.size();
                if (slash == std::string_view::npos || !read_number(c.substr(0, slash), counts[k]))
                    fail("expected the value counts INTS/FLOATS/STRINGS (like 2/1/0), found " + shown(w[1]));
                c.remove_prefix(std::min(slash + 1, c.size()));
            }
        }
        const std::size_t values = w.size() - 2;
        // Each count is checked on its own first: crafted counts can wrap their sum around to `values`.
        const bool each_fits = std::all_of(std::begin(counts), std::end(counts), [&](std::size_t c) { return c <= values; });
        if (!each_fits || counts[0] + counts[1] + counts[2] != values)
            fail(shown(w[1]) + " announces " +
                 (each_fits ? std::to_string(counts[0] + counts[1] + counts[2]) : "more than " + std::to_string(values)) +
                 " values, the line has " + std::to_string(values));
        const bool crease = name == "crease", corner = name == "corner";
        if (name == "interpolateboundary") {
            int k = -1;
            if (counts[0] != 1 || counts[1] != 0 || !read_number(w[2], k) || k < 0 || k > 2)
                fail("interpolateboundary takes one integer: 1 (edge-and-corner) or 2 (edge-only)");
            if (k == 0)
                fail("interpolateboundary 0 (\"none\": faces at the boundary become holes) is not supported; use 1 "
                     "(edge-and-corner) or 2 (edge-only)");
            tags.features.boundary = k == 1 ? rgb::BoundaryInterpolation::EdgeAndCorner : rgb::BoundaryInterpolation::EdgeOnly;
            continue;
        }
        if (!crease && !corner) {
            tags.ignored.add(line.line, name);
            continue;
        }
        const std::size_t per = crease ? 2 : 1;  // vertices per tagged element
        const std::size_t elements = counts[0] / per;
        if (counts[0] == 0 || counts[0] % per != 0)
            fail(std::string(crease ? "a crease needs pairs of vertex indices" : "a corner needs vertex indices") +
                 ", found " + std::to_string(counts[0]));
        if (counts[1] != 1 && counts[1] != elements)
            fail("expected one sharpness, or one per " + std::string(crease ? "edge" : "vertex") + " (" +
                 std::to_string(elements) + "), found " + std::to_string(counts[1]));
        std::vector<std::uint32_t> vertices;
        for (std::size_t i = 0; i < counts[0]; ++i) {
            long long v = -1;
            if (!read_number(w[2 + i], v)) fail("expected a vertex index, found " + shown(w[2 + i]));
            if (v < 0 || static_cast<unsigned long long>(v) >= file_vertices)
                fail("vertex index " + std::to_string(v) + " is out of range (indices are 0-based; the file has " +
                     std::to_string(file_vertices) + " vertices)");
            vertices.push_back(static_cast<std::uint32_t>(v));
        }
        for (std::size_t e = 0; e < elements; ++e) {
            double s = 0.0;
            const std::string_view text = w[2 + counts[0] + (counts[1] == 1 ? 0 : e)];
            if (!read_number(text, s)) fail("expected a sharpness, found " + shown(text));
            const int sharpness = integer_sharpness(s, fail);
            if (crease) {
                if (vertices[2 * e] == vertices[2 * e + 1]) fail("a crease joins two different vertices");
                tags.features.edges.push_back({vertices[2 * e], vertices[2 * e + 1], sharpness});
                tags.edge_lines.push_back(line.line);
            } else {
                tags.features.corners.push_back({vertices[e], sharpness});
                tags.corner_lines.push_back(line.line);
            }
        }
    }
    return tags;
}

void attach_file_tags(const FileTags& tags, LoadedMesh& mesh, const std::string& file) {
    if (tags.ignored.count > 0)
        mesh.warnings.push_back("ignored " + std::to_string(tags.ignored.count) +
                                " tag lines (t) rgbsub does not use (the first on line " +
                                std::to_string(tags.ignored.first_line) + ": " + quoted_file_text(tags.ignored.first_keyword) +
                                "); crease, corner and interpolateboundary are read");
    mesh.sharp_features = {};
    mesh.sharp_features.boundary = tags.features.boundary;
    if (tags.features.edges.empty() && tags.features.corners.empty()) return;
    // The mesh's copies of each file vertex (several where a repair cut a vertex apart).
    std::vector<std::vector<std::uint32_t>> copies;
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
        const std::uint32_t origin = v < mesh.file_vertex.size() ? mesh.file_vertex[v] : v;
        if (origin >= copies.size()) copies.resize(origin + 1);
        copies[origin].push_back(v);
    }
    auto copies_of = [&](std::uint32_t v) { return v < copies.size() ? copies[v] : std::vector<std::uint32_t>{}; };
    std::unordered_set<std::uint64_t> edges;
    for (const rgb::Triangle& t : mesh.triangles)
        for (int i = 0; i < 3; ++i) edges.insert(edge_key(t[i], t[(i + 1) % 3]));
    for (std::size_t i = 0; i < tags.features.edges.size(); ++i) {
        const rgb::EdgeSharpness& e = tags.features.edges[i];
        bool found = false;
        for (std::uint32_t a : copies_of(e.a))
            for (std::uint32_t b : copies_of(e.b))
                if (edges.count(edge_key(a, b))) {
                    mesh.sharp_features.edges.push_back({a, b, e.sharpness});
                    found = true;
                }
        if (!found)
            throw ObjError(ObjProblem::BadTag, file, tags.edge_lines[i],
                           "tag line (t): the crease " + std::to_string(e.a) + "-" + std::to_string(e.b) +
                               " is not an edge of the mesh (vertex indices are 0-based)");
    }
    for (std::size_t i = 0; i < tags.features.corners.size(); ++i) {
        const rgb::VertexSharpness& c = tags.features.corners[i];
        if (copies_of(c.vertex).empty())
            throw ObjError(ObjProblem::BadTag, file, tags.corner_lines[i],
                           "tag line (t): the corner " + std::to_string(c.vertex) + " is a vertex used by no face");
        for (std::uint32_t v : copies_of(c.vertex)) mesh.sharp_features.corners.push_back({v, c.sharpness});
    }
}

void append_tag_lines(const rgb::Mesh& mesh, std::span<const std::uint32_t> obj_index, std::string& out) {
    const rgb::SharpFeatures& features = mesh.base().sharp_features();
    if (features.boundary == rgb::BoundaryInterpolation::EdgeAndCorner) out += "t interpolateboundary 1/0/0 1\n";
    for (const rgb::MeshSharpEdge& e : rgb::sharp_mesh_edges(mesh)) {
        if (e.sharpness <= 0) continue;
        out += "t crease 2/1/0";
        append_integer(out, obj_index[mesh.from_vertex(e.halfedge).idx]);
        append_integer(out, obj_index[mesh.to_vertex(e.halfedge).idx]);
        append_integer(out, static_cast<std::uint64_t>(e.sharpness));
        out += '\n';
    }
    for (const rgb::VertexSharpness& c : features.corners) {
        const rgb::VertexId v(c.vertex);
        const int now = c.sharpness >= rgb::kInfiniteSharpness ? c.sharpness : c.sharpness - rgb::display_level(mesh, v);
        if (now <= 0) continue;
        out += "t corner 1/1/0";
        append_integer(out, obj_index[v.idx]);
        append_integer(out, static_cast<std::uint64_t>(now));
        out += '\n';
    }
}

void append_state_tag_records(const rgb::SharpFeatures& features, std::string& out) {
    if (features == rgb::SharpFeatures{}) return;
    constexpr std::size_t per_line = 8;
    out += std::string("#rgb boundary ") + rgb::boundary_interpolation_name(features.boundary) + "\n";
    for (std::size_t i = 0; i < features.edges.size(); i += per_line) {
        out += "#rgb crease";
        for (std::size_t k = i; k < std::min(features.edges.size(), i + per_line); ++k)
            for (std::uint64_t x : {std::uint64_t(features.edges[k].a), std::uint64_t(features.edges[k].b),
                                    std::uint64_t(features.edges[k].sharpness)})
                append_integer(out, x);
        out += '\n';
    }
    for (std::size_t i = 0; i < features.corners.size(); i += per_line) {
        out += "#rgb corner";
        for (std::size_t k = i; k < std::min(features.corners.size(), i + per_line); ++k)
            for (std::uint64_t x : {std::uint64_t(features.corners[k].vertex), std::uint64_t(features.corners[k].sharpness)})
                append_integer(out, x);
        out += '\n';
    }
}

bool is_state_tag_record(std::string_view kind) { return kind == "boundary" || kind == "crease" || kind == "corner"; }

rgb::SharpFeatures parse_state_tag_records(std::span<const ObjStateLine> lines, const std::string& file) {
    rgb::SharpFeatures features;
    for (const ObjStateLine& line : lines) {
        auto fail = [&](const std::string& reason) {
            throw ObjError(ObjProblem::BadState, file, line.line, "rgbsub state: " + reason);
        };
        const std::vector<std::string_view> w = words(line.text);
        auto number = [&](std::size_t i, std::uint32_t max) {
            std::uint32_t x = 0;
            if (!read_number(w[i], x) || x > max) fail("expected a number up to " + std::to_string(max) + ", found " + shown(w[i]));
            return x;
        };
        if (w[0] == "boundary") {
            const auto b = w.size() == 2 ? rgb::parse_boundary_interpolation(w[1]) : std::nullopt;
            if (!b) fail("boundary must be 'edge-only' or 'edge-and-corner'");
            features.boundary = *b;
        } else if (w[0] == "crease") {
            if ((w.size() - 1) % 3 != 0) fail("crease records are triples A B SHARPNESS");
            for (std::size_t i = 1; i < w.size(); i += 3)
                features.edges.push_back({number(i, UINT32_MAX), number(i + 1, UINT32_MAX),
                                          static_cast<int>(number(i + 2, rgb::kInfiniteSharpness))});
        } else {
            if ((w.size() - 1) % 2 != 0) fail("corner records are pairs V SHARPNESS");
            for (std::size_t i = 1; i < w.size(); i += 2)
                features.corners.push_back({number(i, UINT32_MAX), static_cast<int>(number(i + 1, rgb::kInfiniteSharpness))});
        }
    }
    return features;
}

}  // namespace rgbio
