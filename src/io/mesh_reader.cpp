#include "io/mesh_reader.h"

#include "io/formats/mesh_format.h"
#include "io/obj_reader.h"

namespace rgbio {

LoadedMesh read_mesh_file(const std::string& path, const ReadOptions& options) {
    const MeshFormat format = mesh_format(path);
    return format == MeshFormat::Obj ? read_obj_file(path, options) : read_foreign_file(path, format, options);
}

}  // namespace rgbio
