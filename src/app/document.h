#pragma once
// The mesh being edited and everything about it as a file: its path, whether it has unsaved changes,
// its undo history, and the displayed triangle positions the brush picks on (kept current through the
// core's observer). GL-free.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "app/undo_history.h"
#include "io/mesh_file.h"
#include "render/mesh_changes.h"
#include "render/surface_geometry.h"
#include "rgb/mesh.h"

namespace app {

class Document {
public:
    Document();
    ~Document();
    Document(const Document&) = delete;
    Document& operator=(const Document&) = delete;

    // Replaces the mesh by the file's (throws rgbio::ObjError; the document is unchanged then).
    // Returns the loader's warnings.
    std::vector<std::string> open(const std::string& path);
    // Adopts `mesh` as an unsaved document named `path` (may be empty).
    void adopt(rgb::Mesh mesh, std::string path);
    // Throws rgbio::SaveError. Clears the unsaved mark and makes `path` the document's file.
    void save(const std::string& path, const rgbio::SaveOptions& options);

    rgb::Mesh& mesh() { return mesh_; }
    const rgb::Mesh& mesh() const { return mesh_; }
    const std::string& path() const { return path_; }
    bool dirty() const { return dirty_; }
    // Changes whenever the mesh object is replaced wholesale (open, undo, redo), so that views
    // attached to it re-attach.
    std::uint64_t generation() const { return generation_; }

    // Around every undoable edit: changed == false means the edit did nothing and leaves no step.
    void begin_edit(std::string label);
    void end_edit(bool changed);
    // Puts the mesh back as it was at begin_edit, leaving no step; false if no edit is under way.
    bool abandon_edit();
    bool undo();
    bool redo();
    // The base mesh with other crease and corner tags, as one undoable edit labelled `label`: the
    // vertex set stays, every position follows the new rules. Throws std::invalid_argument for tags
    // the base mesh refuses (the document is unchanged then).
    void set_sharp_features(const rgb::SharpFeatures& features, std::string label);
    UndoHistory& history() { return history_; }
    const UndoHistory& history() const { return history_; }

    // The displayed triangles, brought up to date with the mesh.
    const render::SurfaceGeometry& geometry();

private:
    void replace_mesh(rgb::Mesh mesh);

    rgb::Mesh mesh_;
    std::string path_;
    bool dirty_ = false;
    std::uint64_t generation_ = 0;
    UndoHistory history_;
    render::SurfaceGeometry geometry_;
    std::unique_ptr<render::MeshChanges> changes_;
};

// "name.obj*" for the title bar and panels: the file name, or "untitled", with the unsaved mark.
std::string document_title(const Document& document);

}  // namespace app
