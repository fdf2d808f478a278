#pragma once
// Reading an OBJ file into a validated LoadedMesh (no rgb::Mesh is built here; see mesh_file.h).
#include <string>
#include <string_view>

#include "io/loaded_mesh.h"

namespace rgbio {

// The whole file as bytes; throws ObjError(Unreadable) naming the system's reason (missing,
// a directory, no permission, read error).
std::string read_text_file(const std::string& path);

// Throws ObjError; ObjProblem::Unreadable when the file cannot be opened or read.
LoadedMesh read_obj_file(const std::string& path);

// The same for text already in memory; `name` is used in messages.
// If the text carries an rgbsub state (#rgb lines) that matches its faces, the state is returned
// and the plain content is not re-validated (it is the state's own live mesh). A state that does
// not match the faces (the file was edited elsewhere) is dropped with a warning.
LoadedMesh read_obj_text(std::string_view text, const std::string& name);

}  // namespace rgbio
