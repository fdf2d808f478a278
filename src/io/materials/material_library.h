#pragma once
// Folder io/materials (.mtl libraries): includes io/obj, io/files and the core.
// The .mtl files an OBJ names with mtllib, read with tinyobjloader: each material's name, diffuse
// colour (Kd) and diffuse texture (map_Kd). A library that cannot be read, a material that faces
// use but no library defines, and a texture file that is not there are warnings, not errors: the
// geometry loads either way.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "io/obj/loaded_mesh.h"

namespace rgbio {

// What the material libraries of one mesh may cost together: tinyobjloader keeps about 2.7 KB per
// material, so a hostile library (gigabytes, or one library named thousands of times) would
// exhaust memory. Each library is read once, however often it is named; one that would take the
// libraries beyond either cap is not read (a warning naming it, as for an unreadable one).
inline constexpr std::uintmax_t kMaxMaterialLibraryBytes = std::uintmax_t(16) << 20;
inline constexpr std::size_t kMaxLibraryMaterials = 16384;

// Library names are resolved against obj_folder (absolute ones as they are); '\' is read as '/'
// (Windows exporters write it). Texture paths are resolved against their library's folder.
// Where a library or texture name written in a file points, read against `folder` as above.
std::filesystem::path resolve_file_reference(const std::string& written, const std::filesystem::path& folder);

std::vector<Material> read_material_libraries(const std::vector<std::string>& libraries, const std::filesystem::path& obj_folder,
                                              const FaceLabels& face_materials, std::vector<std::string>& warnings);

}  // namespace rgbio
