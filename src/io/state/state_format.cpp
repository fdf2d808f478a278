#include "io/state/state_format.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstring>

#include "io/obj/number_format.h"
#include "io/obj/obj_error.h"
#include "io/obj/printable_text.h"
#include "io/state/base_colour_state.h"
#include "io/state/crease_tags.h"
#include "io/state/face_label_state.h"
#include "io/state/state_line_reader.h"
#include "rgb/mesh/mesh.h"
#include "rgb/support/parallel.h"
#include "rgb/values/loop_geometry.h"

namespace rgbio {

namespace {

constexpr std::size_t kPerLine = 8;

constexpr std::size_t kNoLine = static_cast<std::size_t>(-1);

// The addresses of one "a" record, after its keyword.
void read_address_record(StateLineReader& r, std::vector<rgb::SurfacePoint>& addresses) {
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
}

bool is_address_record(const ObjStateLine& line, const std::string& file) { return StateLineReader(line, file).word() == "a"; }

// A run of "a" records (one per vertex of a saved file, millions of numbers: most of the state's
// reading time) read in parallel blocks of lines and appended in order. Each block stops at its first
// problem and the lowest block's is reported: the first in line order, as a plain loop reports it.
void read_address_records(std::span<const ObjStateLine> run, const std::string& file, std::vector<rgb::SurfacePoint>& addresses) {
    std::vector<std::vector<rgb::SurfacePoint>> parts(rgb::parallel_blocks(run.size(), 1 << 12));
    rgb::parallel_blocks_for(run.size(), parts.size(), [&](std::size_t b, std::size_t begin, std::size_t end) {
        parts[b].reserve((end - begin) * kPerLine);
        for (std::size_t i = begin; i < end; ++i) {
            StateLineReader r(run[i], file);
            r.word();
            read_address_record(r, parts[b]);
        }
    });
    for (const std::vector<rgb::SurfacePoint>& part : parts) addresses.insert(addresses.end(), part.begin(), part.end());
}

// The position a v line of the saved file holds (`display_levels` as write_state's).
glm::dvec3 written_position(const rgb::Mesh& mesh, rgb::VertexId v, bool limit_positions, std::span<const std::uint8_t> display_levels) {
    return limit_positions ? rgb::limit_position(mesh, v) : rgb::displayed_position(mesh, v, display_levels[v.idx]);
}

// Per base face, the index among the f lines (`face_lines`, or live faces in slot order when empty)
// of the mesh face that is it: the face in its slot when that still has its corners in its order;
// kNoLine otherwise.
std::vector<std::size_t> base_face_lines(const rgb::Mesh& mesh, std::span<const rgb::FaceId> face_lines) {
    const std::span<const rgb::Triangle> triangles = mesh.base().faces();
    std::vector<std::size_t> lines(triangles.size(), kNoLine);
    std::size_t line = 0;
    auto look_at = [&](rgb::FaceId f) {
        if (f.idx < triangles.size()) {
            const auto& v = mesh.face_vertices(f);
            const rgb::Triangle& t = triangles[f.idx];
            if (v[0].idx == t[0] && v[1].idx == t[1] && v[2].idx == t[2]) lines[f.idx] = line;
        }
        ++line;
    };
    if (face_lines.empty())
        for (rgb::FaceId f : mesh.faces()) look_at(f);
    else
        for (rgb::FaceId f : face_lines) look_at(f);
    return lines;
}

void append_uv_section(const rgb::UvChannel& uvs, std::string& out, const std::function<void()>& flush_if_full) {
    out += "#rgb section base-uvs " + std::to_string(uvs.values.size()) + "\n";
    out += std::string("#rgb uv-interpolation ") + rgb::uv_interpolation_name(uvs.interpolation) + "\n";
    for (std::size_t i = 0; i < uvs.values.size(); i += kPerLine) {
        out += "#rgb uv";
        for (std::size_t k = i; k < std::min(uvs.values.size(), i + kPerLine); ++k) {
            append_double(out, uvs.values[k].x);
            append_double(out, uvs.values[k].y);
        }
        out += '\n';
        flush_if_full();
    }
    for (std::size_t i = 0; i < uvs.faces_without_uvs.size(); i += 3 * kPerLine) {
        out += "#rgb uv-untextured";
        for (std::size_t k = i; k < std::min(uvs.faces_without_uvs.size(), i + 3 * kPerLine); ++k) append_integer(out, uvs.faces_without_uvs[k]);
        out += '\n';
        flush_if_full();
    }
    for (std::size_t i = 0; i < uvs.corners.size(); i += kPerLine) {
        out += "#rgb uv-faces";
        for (std::size_t k = i; k < std::min(uvs.corners.size(), i + kPerLine); ++k)
            for (std::uint32_t x : uvs.corners[k]) append_integer(out, x);
        out += '\n';
        flush_if_full();
    }
}

// The base-uvs section's records, checked against its count and the base faces.
rgb::UvChannel parse_uv_section(std::span<const ObjStateLine> records, std::size_t values, std::size_t base_faces,
                                const ObjStateLine& section_line, const std::string& file) {
    rgb::UvChannel uvs;
    bool option_seen = false;
    for (const ObjStateLine& line : records) {
        StateLineReader r(line, file);
        const std::string_view kind = r.word();
        if (kind == "uv-interpolation") {
            const auto option = rgb::parse_uv_interpolation(r.word());
            if (!option) r.fail("uv-interpolation must be 'none', 'corners', 'boundaries' or 'all'");
            uvs.interpolation = *option;
            option_seen = true;
            r.expect_end();
        } else if (kind == "uv") {
            while (!r.at_end()) {
                const double u = r.number<double>();
                uvs.values.push_back({u, r.number<double>()});
            }
            if (uvs.values.size() > values) r.fail("more UVs than the section announces");
        } else if (kind == "uv-untextured") {
            while (!r.at_end()) {
                const auto f = r.number<std::uint32_t>();
                if (f >= base_faces) r.fail("untextured face " + std::to_string(f) + " of " + std::to_string(base_faces));
                if (!uvs.faces_without_uvs.empty() && f <= uvs.faces_without_uvs.back()) r.fail("untextured faces out of order");
                uvs.faces_without_uvs.push_back(f);
            }
        } else {
            while (!r.at_end()) {
                std::array<std::uint32_t, 3> t;
                for (std::uint32_t& x : t)
                    if ((x = r.number<std::uint32_t>()) >= values) r.fail("UV index " + std::to_string(x) + " of " + std::to_string(values) + " UVs");
                uvs.corners.push_back(t);
            }
            if (uvs.corners.size() > base_faces) r.fail("more faces of UV indices than base faces");
        }
    }
    StateLineReader r(section_line, file);
    if (!option_seen) r.fail("section 'base-uvs' has no uv-interpolation record");
    if (uvs.values.size() != values)
        r.fail("section 'base-uvs' announces " + std::to_string(values) + " UVs but holds " + std::to_string(uvs.values.size()));
    if (uvs.corners.size() != base_faces)
        r.fail("section 'base-uvs' gives UV indices for " + std::to_string(uvs.corners.size()) + " faces of " +
               std::to_string(base_faces));
    return uvs;
}

}  // namespace

void write_state(const rgb::Mesh& mesh, bool limit_positions, std::span<const std::uint8_t> display_levels, std::string& out,
                 const std::function<void()>& flush_if_full, std::span<const rgb::FaceId> face_lines, const BaseFaceLabels& labels,
                 const rgb::UvChannel* uvs, std::span<const glm::dvec3> base_colours) {
    const rgb::BaseMesh& base = mesh.base();
    const std::size_t n0 = base.num_vertices();
    out += "# rgbsub adaptive state: the #rgb lines restore the exact RGB mesh; other readers ignore them\n";
    std::string tag_records;
    append_state_tag_records(base.sharp_features(), tag_records);
    const unsigned detail_version =
        base.detail() && needs_face_levels(*base.detail()) ? kFaceLevelDetailStateFormatVersion : kDetailStateFormatVersion;
    const unsigned version = base.detail() ? detail_version : tag_records.empty() ? kStateFormatVersion : kTaggedStateFormatVersion;
    out += "#rgb state " + std::to_string(version) + "\n";
    out += limit_positions ? "#rgb positions limit\n" : "#rgb positions displayed\n";
    out += "#rgb section base-vertices " + std::to_string(n0) + "\n";
    std::size_t run = 0;
    auto end_run = [&](const std::string& record) {
        if (run > 0) out += record + std::to_string(run) + "\n";
        run = 0;
    };
    for (std::uint32_t v = 0; v < n0; ++v) {
        // Where its v line puts it (bit for bit: -0 is not 0 here), it is not repeated.
        const glm::dvec3 p = base.position(v), written = written_position(mesh, rgb::VertexId(v), limit_positions, display_levels);
        if (std::memcmp(&p, &written, sizeof p) == 0) {
            ++run;
            continue;
        }
        end_run("#rgb p-as-v ");
        out += "#rgb p";
        for (int i = 0; i < 3; ++i) append_double(out, p[i]);
        out += '\n';
        flush_if_full();
    }
    end_run("#rgb p-as-v ");
    const std::span<const rgb::Triangle> triangles = base.faces();
    out += "#rgb section base-faces " + std::to_string(triangles.size()) + "\n";
    // A base face still in its own slot, corner for corner, is an f line already.
    const std::vector<std::size_t> face_line = base_face_lines(mesh, face_lines);
    std::size_t first_line = 0;
    std::vector<rgb::Triangle> explicit_faces;
    auto end_explicit = [&] {
        for (std::size_t i = 0; i < explicit_faces.size(); i += kPerLine) {
            out += "#rgb t";
            for (std::size_t k = i; k < std::min(explicit_faces.size(), i + kPerLine); ++k)
                for (std::uint32_t v : explicit_faces[k]) append_integer(out, v);
            out += '\n';
            flush_if_full();
        }
        explicit_faces.clear();
    };
    for (std::size_t f = 0; f < triangles.size(); ++f) {
        if (face_line[f] == kNoLine) {
            end_run("#rgb t-as-f " + std::to_string(first_line) + " ");
            explicit_faces.push_back(triangles[f]);
            continue;
        }
        end_explicit();
        if (run > 0 && face_line[f] != first_line + run) end_run("#rgb t-as-f " + std::to_string(first_line) + " ");
        if (run == 0) first_line = face_line[f];
        ++run;
    }
    end_explicit();
    end_run("#rgb t-as-f " + std::to_string(first_line) + " ");
    // Live vertices in slot order, as capture_state lists them: the base vertices (always live, in
    // slots 0..n0-1) first, then one address per other vertex.
    out += "#rgb section addresses " + std::to_string(mesh.num_vertices() - n0) + "\n";
    std::size_t on_line = 0, index = 0;
    for (rgb::VertexId v : mesh.vertices()) {
        if (index++ < n0) continue;
        if (on_line == 0) out += "#rgb a";
        const rgb::SurfacePoint p = mesh.address(v);
        for (std::uint64_t x : {std::uint64_t(p.face), std::uint64_t(p.a[1]), std::uint64_t(p.a[2]), std::uint64_t(p.level)})
            append_integer(out, x);
        if (++on_line == kPerLine) {
            out += '\n';
            on_line = 0;
            flush_if_full();
        }
    }
    if (on_line > 0) out += '\n';
    if (uvs) append_uv_section(*uvs, out, flush_if_full);
    append_colour_section(base_colours, out, flush_if_full);
    out += tag_records;
    append_face_label_section(labels, triangles.size(), out);
    append_detail_section(base, out, flush_if_full);
    out += "#rgb end\n";
}

std::optional<std::string> drop_foreign_state_lines(std::vector<ObjStateLine>& lines) {
    auto starts_state = [](const ObjStateLine& l) { return l.text.starts_with("state") && (l.text.size() == 5 || l.text[5] == ' ' || l.text[5] == '\t'); };
    const auto first = std::find_if(lines.begin(), lines.end(), starts_state);
    const std::size_t count = lines.size(), first_line = lines.empty() ? 0 : lines.front().line;
    if (first == lines.end()) {
        lines.clear();
        if (count == 0) return std::nullopt;
        return "ignored " + std::to_string(count) + " comment lines starting with #rgb (the first on line " + std::to_string(first_line) +
               "): they are not an rgbsub state, which starts with '#rgb state'";
    }
    auto end = std::find_if(first, lines.end(), [](const ObjStateLine& l) { return l.text == "end"; });
    if (end != lines.end()) ++end;
    const std::size_t foreign_line = first != lines.begin() ? lines.front().line : end != lines.end() ? end->line : 0;
    lines.erase(end, lines.end());
    lines.erase(lines.begin(), first);
    if (lines.size() == count) return std::nullopt;
    return "ignored " + std::to_string(count - lines.size()) + " comment lines starting with #rgb outside the rgbsub state (the first on line " +
           std::to_string(foreign_line) + "): another program's";
}

std::optional<SavedState> parse_state(std::span<const ObjStateLine> lines, const std::string& file, std::size_t body_vertices,
                                      std::size_t body_faces) {
    if (lines.empty()) return std::nullopt;
    StateLineReader header(lines.front(), file);
    // Another program's comments that happen to start with "#rgb": not a state at all.
    if (header.word() != "state") return std::nullopt;
    const unsigned version = header.number<unsigned>();
    if (version < kOldestStateFormatVersion || version > kNewestStateFormatVersion)
        header.fail("state format version " + std::to_string(version) + " (this rgbsub reads versions " +
                    std::to_string(kOldestStateFormatVersion) + " to " + std::to_string(kNewestStateFormatVersion) + ")");
    header.expect_end();

    SavedState saved;
    rgb::MeshState& state = saved.mesh;
    enum class Section { None, BaseVertices, BaseFaces, Addresses, BaseUvs, BaseColours, Detail } section = Section::None;
    std::size_t expected[7] = {0, 0, 0, 0, 0, 0, 0};
    bool seen[7] = {false, false, false, false, false, false, false};
    std::vector<ObjStateLine> uv_records, colour_records, detail_records;
    const ObjStateLine* uv_section_line = nullptr;
    const ObjStateLine* colour_section_line = nullptr;
    const ObjStateLine* detail_section_line = nullptr;
    std::vector<rgb::SurfacePoint> addresses;
    std::vector<ObjStateLine> tag_records;  // version 4
    FaceLabelSectionReader face_labels(file);
    bool ended = false;
    const std::span<const ObjStateLine> records = lines.subspan(1);
    for (std::size_t i = 0; i < records.size(); ++i) {
        const ObjStateLine& line = records[i];
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
            else if (name == "base-uvs") section = Section::BaseUvs;
            else if (name == "base-colours") section = Section::BaseColours;
            else if (name == "detail" && version >= kDetailStateFormatVersion) section = Section::Detail;
            else r.fail("unknown section " + quoted_file_text(name) + " (written by a newer rgbsub?)");
            const auto s = static_cast<int>(section);
            if (seen[s]) r.fail("section '" + std::string(name) + "' appears twice");
            seen[s] = true;
            if (section == Section::BaseUvs) uv_section_line = &line;
            if (section == Section::BaseColours) colour_section_line = &line;
            if (section == Section::Detail) detail_section_line = &line;
            // Counts are bounded by what the lines can hold, so a forged count cannot exhaust memory.
            expected[s] = r.number<std::size_t>(kPerLine * lines.size() + std::max(body_vertices, body_faces));
            r.expect_end();
            if (section == Section::BaseVertices) state.base_positions.reserve(expected[s]);
            if (section == Section::BaseFaces) state.base_triangles.reserve(expected[s]);
            // With room for the base vertices' addresses, which go in front at the end.
            if (section == Section::Addresses) addresses.reserve(state.base_positions.size() + expected[s]);
        } else if (kind == "p") {
            if (section != Section::BaseVertices) r.fail("a base vertex outside its section");
            glm::dvec3 p;
            for (int i = 0; i < 3; ++i) p[i] = r.number<double>();
            r.expect_end();
            state.base_positions.push_back(p);
        } else if (kind == "p-as-v") {
            if (section != Section::BaseVertices) r.fail("base vertices outside their section");
            if (version < kStateFormatVersion) r.fail("'p-as-v' is a record of format 3 on, and the state says format " + std::to_string(version));
            const std::size_t count = r.number<std::size_t>(body_vertices);
            r.expect_end();
            saved.vertices_as_v.push_back({state.base_positions.size(), count, 0});
            state.base_positions.resize(std::min(state.base_positions.size() + count, body_vertices + 1));
        } else if (kind == "t-as-f") {
            if (section != Section::BaseFaces) r.fail("base faces outside their section");
            if (version < kStateFormatVersion) r.fail("'t-as-f' is a record of format 3 on, and the state says format " + std::to_string(version));
            const std::size_t first = r.number<std::size_t>(body_faces), count = r.number<std::size_t>(body_faces);
            r.expect_end();
            saved.faces_as_f.push_back({state.base_triangles.size(), count, first});
            state.base_triangles.resize(std::min(state.base_triangles.size() + count, body_faces + 1));
        } else if (kind == "t") {
            if (section != Section::BaseFaces) r.fail("base faces outside their section");
            while (!r.at_end()) {
                rgb::Triangle t;
                for (std::uint32_t& v : t) v = r.number<std::uint32_t>();
                state.base_triangles.push_back(t);
            }
        } else if (kind == "a") {
            if (section != Section::Addresses) r.fail("addresses outside their section");
            // The lines up to the next other record are "a" records of this section too (nothing in
            // between can end it or belong to another section), read here at once.
            std::size_t run_end = i + 1;
            while (run_end < records.size() && is_address_record(records[run_end], file)) ++run_end;
            read_address_records(records.subspan(i, run_end - i), file, addresses);
            i = run_end - 1;
        } else if (kind == "uv-interpolation" || kind == "uv" || kind == "uv-faces" || kind == "uv-untextured") {
            if (section != Section::BaseUvs) r.fail("texture coordinates outside their section");
            uv_records.push_back(line);
        } else if (kind == kColourRecord) {
            if (section != Section::BaseColours) r.fail("vertex colours outside their section");
            colour_records.push_back(line);
        } else if (is_detail_record(kind, version)) {
            if (section != Section::Detail) r.fail("detail positions outside their section");
            detail_records.push_back(line);
        } else if (version >= kTaggedStateFormatVersion && is_state_tag_record(kind)) {
            tag_records.push_back(line);
        } else if (kind == "end") {
            r.expect_end();
            ended = true;
        } else {
            r.fail("unknown record " + quoted_file_text(kind));
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
    for (const rgb::Triangle& t : state.base_triangles)
        for (std::uint32_t v : t)
            if (v >= state.base_positions.size()) last.fail("a base face uses a missing base vertex");
    // The base vertices' addresses follow once every base face is known (take_from_body).
    addresses.insert(addresses.begin(), state.base_positions.size(), rgb::SurfacePoint{});
    state.vertices = std::move(addresses);
    state.sharp_features = parse_state_tag_records(tag_records, file);
    if (uv_section_line)
        saved.uvs = parse_uv_section(uv_records, expected[static_cast<int>(Section::BaseUvs)], state.base_triangles.size(),
                                     *uv_section_line, file);
    if (colour_section_line)
        saved.colours = parse_colour_section(colour_records, expected[static_cast<int>(Section::BaseColours)], state.base_positions.size(),
                                             *colour_section_line, file);
    if (detail_section_line)
        saved.detail = parse_detail_section(detail_records, expected[static_cast<int>(Section::Detail)], state.base_triangles.size(),
                                            *detail_section_line, file);
    saved.labels = face_labels.finish(state.base_triangles.size(), lines.back());
    return saved;
}

std::optional<std::string> take_from_body(SavedState& saved, std::span<const glm::dvec3> positions, const ObjPolygons& polygons) {
    rgb::MeshState& state = saved.mesh;
    for (const SavedState::Run& run : saved.vertices_as_v) {
        if (run.first_base + run.count > positions.size())
            return "it takes base vertices from v lines " + std::to_string(run.first_base + 1) + " to " +
                   std::to_string(run.first_base + run.count) + ", and the file has " + std::to_string(positions.size());
        std::copy_n(positions.begin() + static_cast<std::ptrdiff_t>(run.first_base), run.count,
                    state.base_positions.begin() + static_cast<std::ptrdiff_t>(run.first_base));
    }
    const std::size_t n0 = state.base_positions.size();
    for (const SavedState::Run& run : saved.faces_as_f) {
        if (run.first_face + run.count > polygons.size())
            return "it takes base faces from f lines " + std::to_string(run.first_face + 1) + " to " +
                   std::to_string(run.first_face + run.count) + ", and the file has " + std::to_string(polygons.size());
        for (std::size_t k = 0; k < run.count; ++k) {
            const ObjPolygon face = polygons[run.first_face + k];
            if (face.vertices.size() != 3 || std::any_of(face.vertices.begin(), face.vertices.end(), [&](std::uint32_t v) { return v >= n0; }))
                return "the face on line " + std::to_string(face.line) + " is not the base face the state takes it for";
            std::copy(face.vertices.begin(), face.vertices.end(), state.base_triangles[run.first_base + k].begin());
        }
    }
    // A base vertex's address is its corner of a base face that uses it.
    std::vector<bool> placed(n0, false);
    for (std::uint32_t f = 0; f < state.base_triangles.size(); ++f)
        for (int c = 0; c < 3; ++c) {
            const std::uint32_t v = state.base_triangles[f][c];
            if (!placed[v]) state.vertices[v] = rgb::corner_point(f, c);
            placed[v] = true;
        }
    return std::nullopt;
}

}  // namespace rgbio
