#pragma once
// The mesh being edited and everything about it as a file: its path, whether it has unsaved changes,
// its undo history, and the displayed triangle positions the brush picks on (kept current through the
// core's observer). GL-free.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/loaded_document.h"
#include "app/surface_index.h"
#include "app/undo_history.h"
#include "io/mesh_file.h"
#include "render/mesh_changes.h"
#include "render/surface_geometry.h"
#include "rgb/mesh/mesh.h"

namespace app {

// Changed face slots (added or freed) a part of the display's catching up takes, with the same share
// of the moved vertices: a few milliseconds.
inline constexpr std::size_t kDisplayPartFaces = std::size_t(1) << 13;
// The smallest part a frame catches up (catch_up_display), whatever time it has left: the display
// always moves on.
inline constexpr std::size_t kMinDisplayPartFaces = std::size_t(1) << 10;

class DisplayPace;

// What the display's catching up cost, summed over its parts until taken (the statistics and the
// benchmarks): the displayed triangles' update and the picking index's, and the changed face slots
// and moved vertices the parts handled.
struct CatchUpTiming {
    double geometry_ms = 0.0, index_ms = 0.0;
    std::size_t parts = 0, faces = 0, vertices = 0;

    void add(const CatchUpTiming& other) {
        geometry_ms += other.geometry_ms;
        index_ms += other.index_ms;
        parts += other.parts;
        faces += other.faces;
        vertices += other.vertices;
    }
};

class Document {
public:
    Document();
    ~Document();
    Document(const Document&) = delete;
    Document& operator=(const Document&) = delete;

    // Replaces the mesh by the file's (throws rgbio::ObjError; the document is unchanged then).
    // Returns the loader's warnings.
    std::vector<std::string> open(const std::string& path);
    // Takes over a document read elsewhere (load_document) as the file `path`; `dirty` for work
    // that is not in that file (a recovery copy).
    void adopt(LoadedDocument loaded, std::string path, bool dirty = false);
    // Adopts `mesh` as an unsaved document named `path` (may be empty).
    void adopt(rgb::Mesh mesh, std::string path);
    // Throws rgbio::SaveError. Writes an OBJ, with_attributes(options), clears the unsaved mark and
    // makes `path` the document's file; a path of another format is an export (rgbio::is_export_path):
    // it writes glTF, PLY, STL, VTU or MSH and leaves the document as it was (its file, its unsaved mark).
    void save(const std::string& path, const rgbio::SaveOptions& options);
    // `options` with what rides on the base mesh (materials, groups, colours from the file read, the
    // exact texture coordinates' layout), for saves made elsewhere (in the background).
    rgbio::SaveOptions with_attributes(rgbio::SaveOptions options);
    // The file's look (materials, vertex colours, texture coordinates) the geometry shows; null if none.
    const std::shared_ptr<const render::SurfaceAppearance>& appearance() const { return geometry_.appearance(); }
    // The state of the document a copy saved elsewhere (in the background) holds, taken when the copy
    // is made.
    struct SaveMark {
        std::uint64_t changes = 0;   // changes()
        std::uint64_t position = 0;  // UndoHistory::position()
    };
    SaveMark save_mark() const { return {changes_count_, history_.position()}; }
    // That copy reached `path`, an OBJ: the file is the document's, and it holds the mesh whenever
    // the history is back at the copy's position.
    void saved_as(const std::string& path, const SaveMark& mark);

    rgb::Mesh& mesh() { return mesh_; }
    const rgb::Mesh& mesh() const { return mesh_; }
    const std::string& path() const { return path_; }
    // Unsaved: the mesh is not at the history's position its file holds (an undo back to it makes
    // the document saved again), or a setting of the file changed since.
    bool dirty() const { return unsaved_setting_ || history_.crossing() || history_.position() != saved_position_; }
    // The file the history's edits start from, as it was opened ("" for a mesh made or recovered
    // here), and whether it has been saved over since, so that it holds some of those edits.
    const std::string& edits_start_from() const { return start_file_; }
    bool start_file_saved_over() const { return start_file_saved_over_; }
    // Counts the changes of the mesh (edits, undo, redo) since the document was made.
    std::uint64_t changes() const { return changes_count_; }

    // Around every undoable edit: changed == false means the edit did nothing and leaves no step
    // (UndoHistory::end_edit).
    void begin_edit(std::string label);
    void end_edit(bool changed, std::optional<std::string> script = std::nullopt, std::optional<std::string> label = std::nullopt);
    // Puts the mesh back as it was at begin_edit, leaving no step; false if no edit is under way.
    // Throws std::logic_error if it cannot (the history is then cleared).
    bool abandon_edit();
    // Undo and redo in pieces (UndoHistory::begin_undo and the rest), so that a step too large for
    // one frame can cross over several (history_job.h).
    bool begin_undo();
    bool begin_redo();
    // True once the step has crossed.
    bool continue_crossing(std::size_t max_steps) { return history_.continue_crossing(max_steps); }
    void stop_crossing() { history_.stop_crossing(); }
    // The base mesh with other crease and corner tags, as one undoable edit labelled `label`: the
    // vertex set stays, every position follows the new rules. Throws std::invalid_argument for tags
    // the base mesh refuses (the document is unchanged then).
    void set_sharp_features(const rgb::SharpFeatures& features, std::string label);
    // Texture coordinates: the base mesh's UV channel if the file had one, and its layout over the
    // current base mesh (rebuilt after a retag), for saving; null without.
    std::shared_ptr<const rgb::UvLayout> uv_layout();
    std::optional<rgb::UvInterpolation> uv_interpolation() const;
    // Another OpenSubdiv face-varying option for the UVs: a setting of the file, not an undoable edit.
    void set_uv_interpolation(rgb::UvInterpolation interpolation);
    UndoHistory& history() { return history_; }
    const UndoHistory& history() const { return history_; }

    // Room for `faces` triangles in the mesh, its geometry and its index: when the room kept so far
    // is less, reserves (reserve_room) kRoomFactor times as many, so that the arrays are not copied
    // again until the mesh has grown that far. Arrays that cross their capacity in the middle of a
    // stroke copy themselves in that frame (0.9 s of one frame at 3.8M triangles: the mesh 0.3 s,
    // the display geometry 0.5 s), so the document keeps room ahead: twice its triangles when it is
    // adopted, twice a whole-mesh job's estimate when one starts, and a quarter more than there are
    // when any edit, undo or redo starts. Without memory for it nothing is reserved: the arrays
    // then grow as the work needs.
    void keep_room(std::size_t faces);

    // The displayed triangles, brought up to date with the mesh. The renderer draws these too.
    const render::SurfaceGeometry& geometry();
    // The displayed triangles as far as they have caught up with the mesh, for drawing: after a large
    // change (the undo of a huge stroke: 140k vertices, 0.35 s of display work at 3.8M triangles)
    // they catch up a part per frame instead of all in one frame.
    const render::SurfaceGeometry& shown() const { return geometry_; }
    // Brings the displayed triangles and the picking index up to date within about `budget`, in
    // parts that `pace` expects to fit the time left (kMinDisplayPartFaces to kDisplayPartFaces
    // face slots; the first one whatever the time left); false while some are left.
    bool catch_up_display(std::chrono::microseconds budget, const DisplayPace& pace);
    // Changed face slots the display has yet to catch up with (all of them after a change of everything).
    std::size_t display_backlog() const;
    // Whether the display has more changes of the mesh left to catch up with than one part of the
    // catching up takes (a few milliseconds).
    bool display_behind() const;
    // Whether the displayed triangles show the mesh as it is and every change of them has been taken
    // (take_display_changes): until then the window keeps drawing frames without input.
    bool display_up_to_date() const;
    // Which positions the triangles show (and picking finds).
    void set_position_source(render::PositionSource source);
    // Whether the triangles carry their distance to the dense mesh, for the distance heat map
    // (render::SurfaceGeometry::set_detail_distance): on only while it is shown, as it costs.
    void set_detail_distance(bool on);
    // The slots geometry() changed since the last call (sorted, coalesced), or that it was rebuilt
    // whole: what the renderer must upload.
    struct DisplayChanges {
        std::vector<render::SlotRange> ranges;
        bool rebuilt = false;
    };
    DisplayChanges take_display_changes();
    // The catching up's cost since the last call.
    CatchUpTiming take_catch_up_timing() { return std::exchange(catch_up_timing_, CatchUpTiming{}); }
    // The nearest front-facing displayed triangle along the ray.
    std::optional<SurfaceHit> pick(const Ray& ray);

private:
    // The start of an undo or redo (`begin`), and what follows the mesh.
    bool begin_crossing(bool (UndoHistory::*begin)());
    void replace_mesh(rgb::Mesh mesh);
    // Rebuilds what follows the mesh from scratch.
    void resync();
    // A new history over the mesh, that of the file `path` (none: "") unless `unsaved`.
    void start_history(std::string path, bool unsaved);
    // The file `path` holds the mesh as it is now, with everything set.
    void mark_saved(const std::string& path);
    // Brings the geometry and index up to date with the next part of the changes (up to `max_faces`
    // changed face slots); true once all are in.
    bool catch_up_part(std::size_t max_faces = kDisplayPartFaces);

    // Keeps room for a quarter more triangles than there are, ahead of an edit, undo or redo.
    void keep_room_for_edit();

    rgb::Mesh mesh_;
    std::size_t room_ = 0;  // triangles keep_room last made room for (the arrays may hold more)
    std::shared_ptr<const rgbio::BaseAttributes> attributes_;  // null for a mesh made, not read
    // Its journal observes the mesh first, before anything that could fail while told of a change.
    UndoHistory history_{mesh_};
    std::string path_;
    std::uint64_t saved_position_ = 0;  // the history's position() the file holds
    bool unsaved_setting_ = false;      // or work that is in no file (a recovered copy, a cage made here)
    std::string start_file_;
    bool start_file_saved_over_ = false;
    std::uint64_t changes_count_ = 0;
    std::optional<rgb::UvChannel> uv_channel_;
    std::shared_ptr<const rgb::UvLayout> uv_layout_;
    std::uint64_t uv_layout_base_ = 0;  // BaseMesh::serial of the base uv_layout_ was built over
    render::SurfaceGeometry geometry_;
    SurfaceIndex index_;
    std::unique_ptr<render::MeshChanges> changes_;
    // How much of changes_'s lists the geometry has caught up with.
    std::size_t faces_caught_up_ = 0, vertices_caught_up_ = 0;
    DisplayChanges display_changes_;
    CatchUpTiming catch_up_timing_;
};

// "name.obj*" for the title bar and panels: the file name, or "untitled", with the unsaved mark.
std::string document_title(const Document& document);

}  // namespace app
