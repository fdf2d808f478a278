#pragma once
// Reading an OBJ file into a validated LoadedMesh (no rgb::Mesh is built here; see mesh_file.h).
#include <string>
#include <string_view>

#include "io/files/file_text.h"
#include "io/obj/loaded_mesh.h"

namespace rgbio {

// Throws ObjError; ObjProblem::Unreadable when the file cannot be opened or read. Also reads the
// material libraries the file names (material_library.h), relative to its folder.
LoadedMesh read_obj_file(const std::string& path, const ReadOptions& options = {});

// The same for text already in memory, without touching any other file (materials stays empty);
// `name` is used in messages.
// If the text carries an rgbsub state (#rgb lines) that matches its faces, the state is returned
// and the plain content is not re-validated (it is the state's own live mesh). A state that does
// not match the faces (the file was edited elsewhere) is dropped with a warning. A file rgbsub wrote
// that was cut short is an ObjError(Truncated) (truncation_check.h).
LoadedMesh read_obj_text(std::string_view text, const std::string& name, const ReadOptions& options = {});

}  // namespace rgbio
