#include "io/mesh_file.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string_view>

#include "io/files/atomic_file.h"
#include "io/files/save_target.h"
#include "io/obj/labelled_faces.h"
#include "io/obj/number_format.h"
#include "io/obj/obj_error.h"
#include "io/obj/truncation_check.h"
#include "io/mesh_reader.h"
#include "io/state/crease_tags.h"
#include "io/state/state_format.h"
#include "rgb/values/limit_normals.h"
#include "rgb/values/loop_geometry.h"
#include "rgb/values/mesh_uvs.h"
#include "rgb/values/uv_evaluator.h"
#include "rgb/values/vertex_channel.h"

namespace rgbio {

namespace {

// `display_levels`: rgb::display_levels, for displayed positions.
glm::dvec3 written_position(const rgb::Mesh& mesh, rgb::VertexId v, SavedPositions which, const std::vector<std::uint8_t>& display_levels) {
    return which == SavedPositions::Limit ? rgb::limit_position(mesh, v) : rgb::displayed_position(mesh, v, display_levels[v.idx]);
}

}  // namespace

rgb::Mesh build_mesh(const LoadedMesh& loaded) {
    if (loaded.adaptive) return *loaded.adaptive;
    return rgb::Mesh(std::make_shared<const rgb::BaseMesh>(loaded.positions, loaded.triangles, loaded.sharp_features));
}

rgb::Mesh load_mesh(const std::string& path, std::vector<std::string>* warnings, const ReadOptions& options) {
    LoadedMesh loaded = read_mesh_file(path, options);
    if (warnings) warnings->insert(warnings->end(), loaded.warnings.begin(), loaded.warnings.end());
    if (loaded.adaptive) return std::move(*loaded.adaptive);
    return build_mesh(loaded);
}

namespace {

// The text collected in one string (format_obj).
struct StringOutput {
    std::string text;
    std::string& buffer() { return text; }
    void flush_if_full() {}
};

void append_vector(std::string& out, const char* keyword, const glm::dvec3& x) {
    out += keyword;
    for (int i = 0; i < 3; ++i) append_double(out, x[i]);
}

// Records of one section of the file written so far, told to its part of the progress every few
// thousand (so that reporting costs nothing next to formatting them).
class WrittenRecords {
public:
    WrittenRecords(rgb::ProgressSpan span, double total) : span_(span), total_(std::max(total, 1.0)) {}
    void add() {
        constexpr std::uint64_t kPerReport = 4096;
        if (++count_ % kPerReport == 0) span_.reach(std::min(1.0, static_cast<double>(count_) / total_));
    }
    void done() const { span_.done(); }

private:
    rgb::ProgressSpan span_;
    double total_;
    std::uint64_t count_ = 0;
};

// Appends the OBJ text record by record; Output is StringOutput or AtomicFileWriter (save_mesh
// streams the file instead of holding it whole); positions and faces are computed as they are
// written. `output_folder`: where the file goes, for the mtllib references.
template <class Output>
void write_obj(const rgb::Mesh& mesh, const SaveOptions& options, const std::string& output_folder, Output& output) {
    const BaseAttributes* attributes = options.attributes.get();
    // Level-0 texture coordinates are the base mesh's: written only while the mesh is that.
    const bool base_data = attributes && is_base_mesh(mesh);
    // Vertex colours follow the position rules (rgb/values/vertex_channel.h): written at every level, at the
    // same level as the positions beside them.
    const std::vector<glm::dvec3> colours =
        attributes && !attributes->colours.empty()
            ? rgb::vertex_channel_values(mesh, attributes->colours,
                                         options.positions == SavedPositions::Limit ? rgb::ChannelLevel::Limit : rgb::ChannelLevel::Displayed)
            : std::vector<glm::dvec3>();
    // The exact UV channel, when there is one, says every corner's UV at every level.
    const bool texcoords = !options.uvs && base_data && !attributes->triangle_texcoords.empty();
    const LabelledFaceOrder order = labelled_face_order(mesh, attributes ? attributes->labels : BaseFaceLabels{});

    // The progress in records written, each section its share of the time: a v line (three
    // positions computed and written with 17 digits) takes about six times an f line, a state line
    // (eight addresses) about eight (measured at 1M and 3.8M triangles).
    const std::size_t texcoord_lines = options.uvs ? 0 : (texcoords ? attributes->texcoords.size() : 0);
    const double vertex_records = static_cast<double>(mesh.num_vertices()) * (options.normals ? 2.0 : 1.0) + static_cast<double>(texcoord_lines);
    const double face_records = static_cast<double>(order.faces.size());
    const double state_records = options.state ? static_cast<double>(mesh.num_vertices()) / 8.0 : 0.0;
    const double vertex_time = 6.0 * vertex_records, face_time = face_records, state_time = 8.0 * state_records;
    const double all_time = std::max(1.0, vertex_time + face_time + state_time);
    const double faces_from = vertex_time / all_time, state_from = (vertex_time + face_time) / all_time;
    WrittenRecords written_vertices(options.progress.part(0.0, faces_from), vertex_records);
    WrittenRecords written_faces(options.progress.part(faces_from, state_from), face_records);
    WrittenRecords written_state(options.progress.part(state_from, 1.0), state_records);

    std::vector<std::uint32_t> obj_index(mesh.vertex_capacity(), UINT32_MAX);
    std::uint32_t written = 0;
    for (rgb::VertexId v : mesh.vertices()) obj_index[v.idx] = written++;
    // Made before the header, which counts them: a file cut just before its t lines is then known as cut.
    std::string tag_lines;
    append_tag_lines(mesh, obj_index, tag_lines);

    std::string& out = output.buffer();
    out += "# rgbsub mesh: " + std::to_string(mesh.num_vertices()) + " vertices, " + std::to_string(order.faces.size()) +
           " triangles; positions: " + (options.positions == SavedPositions::Limit ? "limit" : "displayed") +
           tag_lines_note(static_cast<std::size_t>(std::count(tag_lines.begin(), tag_lines.end(), '\n'))) +
           // Lets the reader tell a file cut before its state from one saved without it.
           (options.state ? std::string(kSavedStateNote) : std::string()) + "\n";
    if (attributes)
        for (const std::string& library : library_references(*attributes, output_folder)) out += "mtllib " + library + "\n";
    const std::vector<std::uint8_t> display_levels =
        options.positions == SavedPositions::Limit ? std::vector<std::uint8_t>() : rgb::display_levels(mesh);
    for (rgb::VertexId v : mesh.vertices()) {
        append_vector(out, "v", written_position(mesh, v, options.positions, display_levels));
        if (!colours.empty())
            for (int c = 0; c < 3; ++c) append_double(out, colours[v.idx][c]);
        out += '\n';
        output.flush_if_full();
        written_vertices.add();
    }
    rgb::MeshUvs uvs;
    if (options.uvs) {
        rgb::UvEvaluator evaluator(mesh.base(), *options.uvs);
        uvs = rgb::mesh_uvs(mesh, evaluator, options.positions == SavedPositions::Limit);
        for (const glm::dvec2& uv : uvs.values) {
            out += "vt";
            append_double(out, uv.x);
            append_double(out, uv.y);
            out += '\n';
            output.flush_if_full();
            written_vertices.add();
        }
    }
    if (texcoords)
        for (const glm::dvec2& uv : attributes->texcoords) {
            out += "vt";
            for (int c = 0; c < 2; ++c) append_double(out, uv[c]);
            out += '\n';
            output.flush_if_full();
            written_vertices.add();
        }
    if (options.normals) {
        const std::vector<glm::dvec3> normals = rgb::limit_normals(mesh);
        for (rgb::VertexId v : mesh.vertices()) {
            append_vector(out, "vn", normals[v.idx]);
            out += '\n';
            output.flush_if_full();
            written_vertices.add();
        }
    }
    auto block = order.blocks.begin();
    for (std::size_t i = 0; i < order.faces.size(); ++i) {
        if (block != order.blocks.end() && block->first == i) out += (block++)->lines;
        out += 'f';
        const rgb::FaceId f = order.faces[i];
        for (int c = 0; c < 3; ++c) {
            const std::uint64_t index = std::uint64_t(obj_index[mesh.face_vertices(f)[c].idx]) + 1;
            std::uint32_t uv = kNoIndex;
            if (options.uvs) uv = uvs.corners[f.idx][c] == rgb::MeshUvs::kNone ? kNoIndex : uvs.corners[f.idx][c];
            else if (texcoords) uv = base_corner_texcoord(mesh, *attributes, f, c);
            append_integer(out, index);
            if (uv != kNoIndex) {
                out += '/';
                append_digits(out, std::uint64_t(uv) + 1);
            }
            if (options.normals) {
                out += uv != kNoIndex ? "/" : "//";
                append_digits(out, index);
            }
        }
        out += '\n';
        output.flush_if_full();
        written_faces.add();
    }
    written_vertices.done();
    written_faces.done();
    out += tag_lines;
    if (options.state)
        write_state(mesh, options.positions == SavedPositions::Limit, display_levels, out,
                    [&] {
                        output.flush_if_full();
                        written_state.add();
                    },
                    order.faces, attributes ? attributes->labels : BaseFaceLabels{}, options.uvs ? &options.uvs->channel() : nullptr,
                    attributes ? std::span<const glm::dvec3>(attributes->colours) : std::span<const glm::dvec3>());
}

}  // namespace

std::string format_obj(const rgb::Mesh& mesh, const SaveOptions& options) {
    StringOutput output;
    output.text.reserve(40 * mesh.num_vertices() + 30 * mesh.num_faces());
    write_obj(mesh, options, options.attributes ? options.attributes->library_folder : std::string(), output);
    options.progress.done();
    return std::move(output.text);
}

void save_mesh(const rgb::Mesh& mesh, const std::string& path, const SaveOptions& options) {
    // The real file's folder: saved through a symbolic link, the file lives where the link leads.
    const std::string folder = resolve_save_target(path).folder;
    AtomicFileWriter file(path);
    write_obj(mesh, options, folder, file);
    file.commit();
    options.progress.done();
}

}  // namespace rgbio
