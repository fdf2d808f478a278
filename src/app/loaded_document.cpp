#include "app/loaded_document.h"

#include "io/base_uvs.h"

namespace app {

LoadedDocument load_document(const std::string& path, render::PositionSource source) {
    LoadedDocument loaded{rgb::Mesh(), render::SurfaceGeometry(source), SurfaceIndex(), {}, std::nullopt};
    rgbio::MeshWithUvs read = rgbio::load_mesh_with_uvs(path, loaded.warnings);
    loaded.mesh = std::move(read.mesh);
    loaded.uvs = std::move(read.uvs);
    loaded.geometry.rebuild(loaded.mesh);
    loaded.index.rebuild(loaded.mesh, loaded.geometry);
    return loaded;
}

}  // namespace app
