#include "io/obj_reader.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <functional>

#include "io/materials/material_library.h"
#include "io/obj/obj_error.h"
#include "io/obj/obj_parser.h"
#include "io/obj/truncation_check.h"
#include "io/repair/mesh_validation.h"
#include "io/state/base_colour_state.h"
#include "io/state/crease_tags.h"
#include "io/state/face_label_state.h"
#include "io/state/state_format.h"
#include "rgb/mesh/mesh.h"
#include "rgb/values/restore_state.h"

namespace rgbio {

namespace {

// Shares of the time of reading a saved file, measured on saved files of 1M and 6M triangles (the
// steps are linear, so the shares hold at any size): reading the bytes, parsing the text (of what
// follows), parsing the state's lines and restoring the mesh (of what follows that).
constexpr double kRead = 0.03, kParsed = 0.28, kStateParsed = 0.04, kRestored = 0.97;

// The mesh the state describes, if it is the body's own: one address per v line, only triangles, a
// valid RGB mesh with these faces, exactly these positions and the labels of their base faces.
// Otherwise the reason it is not. The state is completed on the way (its faces are the f lines').
std::shared_ptr<rgb::Mesh> adaptive_mesh(SavedState& saved, const ObjRecords& records, std::string& reason,
                                         const rgb::ProgressSpan& progress) {
    if (saved.mesh.vertices.size() != records.positions.size()) {
        reason = "it describes " + std::to_string(saved.mesh.vertices.size()) + " vertices, the file has " +
                 std::to_string(records.positions.size());
        return nullptr;
    }
    if (std::optional<std::string> missing = take_from_body(saved, records.positions, records.polygons)) {
        reason = std::move(*missing);
        return nullptr;
    }
    const std::span<const std::uint32_t> corners = records.polygons.all_vertices();
    if (corners.size() != 3 * records.polygons.size()) {
        for (const ObjPolygon& p : records.polygons)
            if (p.vertices.size() != 3) {
                reason = "the file has a face with " + std::to_string(p.vertices.size()) + " vertices (line " + std::to_string(p.line) + ")";
                return nullptr;
            }
    }
    if (saved.detail) {
        saved.mesh.detail = detail_over(*saved.detail, saved.mesh.base_positions, saved.mesh.base_triangles, reason);
        if (!saved.mesh.detail) return nullptr;
    }
    // All triangles: their corners are the faces, three by three.
    saved.mesh.faces.resize(records.polygons.size());
    // Not with none: a file without faces is refused later, and memcpy takes no null pointers.
    if (!corners.empty()) std::memcpy(saved.mesh.faces.data(), corners.data(), corners.size_bytes());
    // Colours removed elsewhere stay removed; colours changed elsewhere win over the state, as positions do.
    const bool body_colours =
        !records.colours.empty() && std::find(records.has_colour.begin(), records.has_colour.end(), 0) == records.has_colour.end();
    if (!body_colours) saved.colours.clear();
    // The saved colours are at the positions' level; restored in the positions' pass, for speed.
    rgb::RestoredChannel colours{saved.colours, saved.limit_positions ? rgb::ChannelLevel::Limit : rgb::ChannelLevel::Displayed, {}};
    rgb::RestoredPositions written{saved.limit_positions ? rgb::ChannelLevel::Limit : rgb::ChannelLevel::Displayed, {}};
    std::shared_ptr<rgb::Mesh> mesh;
    try {
        mesh = std::make_shared<rgb::Mesh>(
            rgb::restore_state(saved.mesh, progress.part(0.0, kRestored), saved.colours.empty() ? nullptr : &colours, &written));
    } catch (const std::invalid_argument& e) {
        reason = std::string("it does not fit the file's faces (") + e.what() + ")";
        return nullptr;
    }
    // An edit elsewhere (moved or scaled vertices) must win over the state, not be silently undone.
    std::size_t differing = 0;
    for (std::size_t i = 0; i < written.values.size(); ++i) differing += written.values[i] != records.positions[i];
    if (differing > 0) {
        reason = std::to_string(differing) + " of " + std::to_string(records.positions.size()) +
                 " vertex positions differ from the ones it gives";
        return nullptr;
    }
    if (!saved.colours.empty())
        if (std::optional<std::string> mismatch = colour_mismatch(colours.values, records)) {
            reason = std::move(*mismatch);
            return nullptr;
        }
    // Saved without labels, the body's (added elsewhere) become the base faces'.
    if (saved.labels.empty()) saved.labels = body_labels(*mesh, records);
    if (const std::optional<std::string> mismatch = label_mismatch(*mesh, saved.labels, records)) {
        reason = *mismatch;
        return nullptr;
    }
    return mesh;
}

// A state's mesh, or the plain mesh with a warning saying why the state was not used.
// release_text() is called once a state is parsed: nothing after needs the text. The records are
// used up (the positions move into the result).
LoadedMesh read_records(ObjRecords&& records, const std::string& name, const ReadOptions& options,
                        const std::function<void()>& release_text, std::optional<std::string> foreign_lines) {
    const std::size_t vertices = records.positions.size();
    // Read before the text is released: the tag lines are views into it, and a saved file that does
    // not match its state (edited elsewhere) loads as a plain mesh with these tags.
    const FileTags tags = parse_tag_lines(records.tags, vertices, name);
    std::vector<std::string> warnings;
    if (foreign_lines) warnings.push_back(std::move(*foreign_lines));
    if (!records.state.empty()) {
        // drop_foreign_state_lines has left only a state that starts with '#rgb state'.
        std::optional<SavedState> saved = parse_state(records.state, name, records.positions.size(), records.polygons.size());
        options.progress.reach(kStateParsed);
        if (saved) {
            release_text();
            std::string reason;
            if (std::shared_ptr<rgb::Mesh> mesh = adaptive_mesh(*saved, records, reason, options.progress.part(kStateParsed, 1.0))) {
                LoadedMesh loaded = saved_mesh_content(records, std::move(saved->mesh.faces));
                loaded.adaptive = std::move(mesh);
                loaded.base_uvs = std::move(saved->uvs);
                loaded.base_colours = std::move(saved->colours);
                loaded.adaptive_labels = std::move(saved->labels);
                loaded.warnings.insert(loaded.warnings.begin(), warnings.begin(), warnings.end());
                options.progress.done();
                return loaded;
            }
            warnings.push_back("the rgbsub state (#rgb lines) does not match the file, which was probably edited by another "
                               "program: " + reason + "; it is loaded as a plain mesh");
        }
    }
    LoadedMesh loaded = validate_mesh(records, name, options);
    attach_file_tags(tags, loaded, name);
    loaded.warnings.insert(loaded.warnings.begin(), warnings.begin(), warnings.end());
    options.progress.done();
    return loaded;
}

}  // namespace

namespace {

// What read_obj_text does; `owned`, when not null, holds the text itself, given up by the caller and
// released once a saved file's state is parsed (its mesh is built without the text, which for a
// 6M-triangle file is 370 MB).
LoadedMesh read_text(std::string_view text, FileText* owned, const std::string& name, const ReadOptions& options) {
    const std::optional<SavedFileHeader> header = read_saved_file_header(text);
    const rgb::ProgressSpan parsing = options.progress.part(0.0, kParsed);
    ReadOptions rest = options;
    rest.progress = options.progress.part(kParsed, 1.0);
    if (!header) {
        ObjRecords records = parse_obj(text, name, parsing);
        std::optional<std::string> foreign = drop_foreign_state_lines(records.state);
        return read_records(std::move(records), name, rest, [] {}, std::move(foreign));
    }
    ObjRecords records;
    std::optional<std::string> foreign;
    try {
        records = parse_obj(text, name, parsing);
        foreign = drop_foreign_state_lines(records.state);
        check_saved_file_complete(*header, records, text, name);
    } catch (const ObjError& error) {
        throw truncation_or(error, *header, text, name);
    }
    const TextEnd end = text_end(records, text);
    try {
        return read_records(
            std::move(records), name, rest,
            [owned] {
                if (owned) owned->release();
            },
            std::move(foreign));
    } catch (const ObjError& error) {
        throw truncation_or(error, *header, end, name);
    }
}

}  // namespace

LoadedMesh read_obj_text(std::string_view text, const std::string& name, const ReadOptions& options) {
    return read_text(text, nullptr, name, options);
}

LoadedMesh read_obj_file(const std::string& path, const ReadOptions& options) {
    FileText text = read_file_text(path, options.progress.part(0.0, kRead));
    ReadOptions rest = options;
    rest.progress = options.progress.part(kRead, 1.0);
    LoadedMesh loaded;
    try {
        loaded = read_text(text.view(), &text, path, rest);
    } catch (...) {
        // Whatever the reader made of the zeros in place of a vanished end, the cause is the file's shrinking.
        text.check_not_shrunk();
        throw;
    }
    text.check_not_shrunk();
    loaded.materials = read_material_libraries(loaded.material_libraries, std::filesystem::path(path).parent_path(),
                                               loaded.face_materials, loaded.warnings);
    return loaded;
}

}  // namespace rgbio
