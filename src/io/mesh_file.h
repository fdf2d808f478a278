#pragma once
// OBJ files <-> rgb::Mesh: the entry points for the editor and the CLI.
//
// A saved file is a standard OBJ of the current adaptive mesh (v, optional vn, f) followed by the
// exact adaptive state in "#rgb" comment lines (state_format.h). Loading such a file restores the
// adaptive mesh slot for slot; a plain OBJ loads as a base mesh (all green, level 0).
#include <cstddef>
#include <string>
#include <vector>

#include "io/loaded_mesh.h"
#include "rgb/mesh.h"

namespace rgbio {

// Builds the mesh a LoadedMesh describes. Throws ObjError(BadState) if a saved state is not a valid
// RGB mesh; `file` is used in that message.
rgb::Mesh build_mesh(const LoadedMesh& loaded, const std::string& file);

// read_obj_file + build_mesh. Warnings (fixes, ignored content) are appended to *warnings if given.
rgb::Mesh load_mesh(const std::string& path, std::vector<std::string>* warnings = nullptr, const ReadOptions& options = {});

enum class SavedPositions {
    Displayed,  // what the viewer shows: p^k at each vertex's display level
    Limit,      // p^inf where the current mesh holds the vertex's ring; otherwise displayed (counted)
};

struct SaveOptions {
    SavedPositions positions = SavedPositions::Displayed;
    bool normals = false;      // area-weighted vertex normals of the written positions
    bool state = true;         // the #rgb lines that make the file resumable
};

struct SaveReport {
    // Vertices written at their displayed position because their limit position is not available
    // in the current mesh (only with SavedPositions::Limit; computing it would change the topology).
    std::size_t limit_fallbacks = 0;
};

// The file content. The mesh is not modified (limit positions may be cached, see try_limit_position).
std::string format_obj(const rgb::Mesh& mesh, const SaveOptions& options, SaveReport* report = nullptr);

// format_obj written atomically (atomic_file.h). Throws SaveError.
SaveReport save_mesh(const rgb::Mesh& mesh, const std::string& path, const SaveOptions& options = {});

}  // namespace rgbio
