#include "app/loaded_document.h"

#include "io/base_uvs.h"
#include "app/file_appearance.h"

namespace app {

LoadedDocument load_document(const std::string& path, render::PositionSource source) {
    LoadedDocument loaded{rgb::Mesh(), nullptr, render::SurfaceGeometry(source), SurfaceIndex(), {}, std::nullopt};
    rgbio::LoadedAsset asset = rgbio::load_asset(path, &loaded.warnings);
    loaded.mesh = std::move(asset.mesh);
    loaded.attributes = std::move(asset.attributes);
    loaded.uvs = std::move(asset.uvs);
    loaded.geometry.set_appearance(file_appearance(*loaded.attributes, loaded.uvs, loaded.mesh.base().num_faces(), loaded.warnings));
    loaded.geometry.rebuild(loaded.mesh);
    loaded.index.rebuild(loaded.mesh, loaded.geometry);
    return loaded;
}

}  // namespace app
