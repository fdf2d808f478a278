#pragma once
// A mesh read from a file with everything the editor shows and picks on already built, so that
// reading can happen away from the window's thread and handing it over costs nothing.
#include <optional>
#include <memory>
#include <string>
#include <vector>

#include "app/surface_index.h"
#include "io/base_attributes.h"
#include "render/surface_geometry.h"
#include "rgb/mesh/mesh.h"
#include "rgb/support/progress.h"
#include "rgb/values/uv_layout.h"

namespace app {

struct LoadedDocument {
    rgb::Mesh mesh;
    std::shared_ptr<const rgbio::BaseAttributes> attributes;  // what rides on its base (never null)
    render::SurfaceGeometry geometry;
    SurfaceIndex index;
    std::vector<std::string> warnings;
    std::optional<rgb::UvChannel> uvs;  // the base mesh's texture coordinates (io/base_uvs.h)
};

// Room for `faces` triangles in the mesh and in what follows it (its vertices about half as many),
// reserved ahead where a copy costs no frame: a file's thread, adopting a mesh, the start of a job
// from its estimate. Growing by doubling instead copies every array in whichever frame crosses
// the capacity (0.3 s at 3.8M triangles). Reserved room is address space only until it is used.
void reserve_room(rgb::Mesh& mesh, render::SurfaceGeometry& geometry, SurfaceIndex& index, std::size_t faces);

// Headroom a document gets when it is read or adopted: twice its triangles.
inline constexpr std::size_t kRoomFactor = 2;

// Reads `path` (throws rgbio::ObjError) and builds its geometry at `source` positions, with the
// file's look (file_appearance.h), and its index. `progress` hears how far it is.
LoadedDocument load_document(const std::string& path, render::PositionSource source, const rgb::ProgressSpan& progress = {});

}  // namespace app
