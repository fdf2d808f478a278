#pragma once
// OBJ files <-> rgb::Mesh: the entry points for the editor and the CLI.
//
// A saved file is a standard OBJ of the current adaptive mesh (v, optional vt and vn, f, and what rides
// on the base mesh: base_attributes.h) followed by the
// exact adaptive state in "#rgb" comment lines (state_format.h). Loading such a file restores the
// adaptive mesh slot for slot; a plain OBJ loads as a base mesh (all green, level 0).
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "io/base_attributes.h"
#include "io/formats/mesh_format.h"
#include "io/obj/loaded_mesh.h"
#include "rgb/mesh/mesh.h"
#include "rgb/support/progress.h"
#include "rgb/values/uv_layout.h"

namespace rgbio {

// The mesh a LoadedMesh describes: its adaptive mesh if it has one, else the base mesh of its faces.
rgb::Mesh build_mesh(const LoadedMesh& loaded);

// read_mesh_file (any format) + build_mesh. Warnings (fixes, ignored content) are appended to *warnings if given.
rgb::Mesh load_mesh(const std::string& path, std::vector<std::string>* warnings = nullptr, const ReadOptions& options = {});

enum class SavedPositions {
    Displayed,  // what the viewer shows: p^k at each vertex's display level
    Limit,      // p^inf, the vertex's point of the Loop limit surface
};

struct SaveOptions {
    SavedPositions positions = SavedPositions::Displayed;
    bool normals = false;      // vn: exact normals of the Loop limit surface (rgb/values/limit_normals.h)
    bool state = true;         // the #rgb lines that make the file resumable
    MshEncoding msh = MshEncoding::Ascii;  // a .msh output (io/formats/format_writers.h): ASCII or binary
    // Texture coordinates (io/base_uvs.h): vt lines with every corner's exact UV (at its vertex's
    // display level, or the limit beside limit positions) and f v/vt corners; the state keeps the
    // base channel. Must have been built over the saved mesh's base mesh. Null: none.
    std::shared_ptr<const rgb::UvLayout> uvs = nullptr;
    // What rides on the base mesh (labels, material libraries, texture coordinates, colours), written
    // with the mesh: faces grouped by label (labelled_faces.h), mtllib references that still lead to
    // the libraries, and texture coordinates and colours while the mesh is at level 0
    // (dropped_attributes says what a refined mesh leaves out). Null: none.
    std::shared_ptr<const BaseAttributes> attributes = nullptr;
    // Told how far the writing is: vertices, then faces, then the state's vertices written.
    rgb::ProgressSpan progress = {};
};

// The file content. The mesh is not modified (limit positions may be cached, see loop_geometry.h).
std::string format_obj(const rgb::Mesh& mesh, const SaveOptions& options);

// The same text streamed to the file through AtomicFileWriter (atomic_file.h), a few MB at a time.
// Throws SaveError.
void save_mesh(const rgb::Mesh& mesh, const std::string& path, const SaveOptions& options = {});

}  // namespace rgbio
