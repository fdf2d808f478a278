#pragma once
// Folder io/materials (.mtl libraries): includes io/obj, io/files and the core.
// The .mtl files an OBJ names with mtllib, read with tinyobjloader: each material's name, diffuse
// colour (Kd) and diffuse texture (map_Kd). A library that cannot be read, a material that faces
// use but no library defines, and a texture file that is not there are warnings, not errors: the
// geometry loads either way.
#include <filesystem>
#include <string>
#include <vector>

#include "io/obj/loaded_mesh.h"

namespace rgbio {

// Library names are resolved against obj_folder (absolute ones as they are); '\' is read as '/'
// (Windows exporters write it). Texture paths are resolved against their library's folder.
// Where a library or texture name written in a file points, read against `folder` as above.
std::filesystem::path resolve_file_reference(const std::string& written, const std::filesystem::path& folder);

std::vector<Material> read_material_libraries(const std::vector<std::string>& libraries, const std::filesystem::path& obj_folder,
                                              const FaceLabels& face_materials, std::vector<std::string>& warnings);

}  // namespace rgbio
