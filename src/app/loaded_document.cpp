#include "app/loaded_document.h"

#include "io/base_uvs.h"
#include "io/scale_check.h"
#include "app/file_appearance.h"

namespace app {

namespace {

// Shares of the time of opening a saved file: reading the mesh, then building its geometry (the
// index takes the rest). Measured on saved files of 1M and 6M triangles.
constexpr double kRead = 0.66, kGeometryBuilt = 0.85;

}  // namespace

void reserve_room(rgb::Mesh& mesh, render::SurfaceGeometry& geometry, SurfaceIndex& index, std::size_t faces) {
    // Below the capacity each reserve does nothing.
    const std::size_t vertices = faces / 2 + mesh.base().num_vertices();
    mesh.reserve(faces, vertices);
    geometry.reserve(faces, vertices);
    index.reserve(faces);
}

LoadedDocument load_document(const std::string& path, render::PositionSource source, const rgb::ProgressSpan& progress) {
    LoadedDocument loaded{rgb::Mesh(), nullptr, render::SurfaceGeometry(source), SurfaceIndex(), {}, std::nullopt};
    rgbio::LoadedAsset asset = rgbio::load_asset(path, &loaded.warnings, {.progress = progress.part(0.0, kRead)});
    // The editor works in doubles and draws in 32-bit floats: a mesh either cannot hold is refused with
    // the reason rather than shown blank (issue 30 item 14).
    rgbio::check_scale(asset.mesh.base().positions(), {rgbio::kDoubleScale, rgbio::kFloatScale}, path, "open");
    loaded.mesh = std::move(asset.mesh);
    loaded.attributes = std::move(asset.attributes);
    loaded.uvs = std::move(asset.uvs);
    loaded.geometry.set_appearance(file_appearance(*loaded.attributes, loaded.uvs, loaded.mesh.base().num_faces(), loaded.warnings));
    reserve_room(loaded.mesh, loaded.geometry, loaded.index, kRoomFactor * loaded.mesh.num_faces());
    loaded.geometry.rebuild(loaded.mesh);
    progress.reach(kGeometryBuilt);
    loaded.index.rebuild(loaded.mesh, loaded.geometry);
    progress.done();
    return loaded;
}

}  // namespace app
