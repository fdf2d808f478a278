#include "app/loaded_document.h"

#include "io/mesh_file.h"

namespace app {

LoadedDocument load_document(const std::string& path, render::PositionSource source) {
    LoadedDocument loaded{rgb::Mesh(), render::SurfaceGeometry(source), SurfaceIndex(), {}};
    loaded.mesh = rgbio::load_mesh(path, &loaded.warnings);
    loaded.geometry.rebuild(loaded.mesh);
    loaded.index.rebuild(loaded.mesh, loaded.geometry);
    return loaded;
}

}  // namespace app
