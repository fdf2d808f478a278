#include "io/mesh_export.h"

#include "io/formats/format_writers.h"
#include "io/gltf_export.h"
#include "rgb/values/loop_geometry.h"
#include "rgb/values/vertex_channel.h"

namespace rgbio {

ExportMesh export_mesh(const rgb::Mesh& mesh, const SaveOptions& options) {
    ExportMesh out;
    const bool limit = options.positions == SavedPositions::Limit;
    const BaseAttributes* attributes = options.attributes.get();
    const std::vector<glm::dvec3> colours =
        attributes && !attributes->colours.empty()
            ? rgb::vertex_channel_values(mesh, attributes->colours, limit ? rgb::ChannelLevel::Limit : rgb::ChannelLevel::Displayed)
            : std::vector<glm::dvec3>();
    std::vector<std::uint32_t> index(mesh.vertex_capacity(), kNoIndex);
    out.positions.reserve(mesh.num_vertices());
    for (rgb::VertexId v : mesh.vertices()) {
        index[v.idx] = static_cast<std::uint32_t>(out.positions.size());
        out.positions.push_back(limit ? rgb::limit_position_uncached(mesh, v) : rgb::displayed_position(mesh, v));
        if (!colours.empty()) out.colours.push_back(colours[v.idx]);
    }
    out.triangles.reserve(mesh.num_faces());
    for (rgb::FaceId f : mesh.faces()) {
        const auto& v = mesh.face_vertices(f);
        out.triangles.push_back({index[v[0].idx], index[v[1].idx], index[v[2].idx]});
        out.levels.push_back(static_cast<std::uint8_t>(mesh.level(f)));
        out.rgb_colours.push_back(static_cast<std::uint8_t>(mesh.type(f).colour));
    }
    return out;
}

bool is_export_path(const std::string& path) { return output_format(path) != OutputFormat::Obj; }

void save_mesh_file(const rgb::Mesh& mesh, const std::string& path, const SaveOptions& options) {
    const OutputFormat format = output_format(path);
    if (format == OutputFormat::Obj) return save_mesh(mesh, path, options);
    if (format == OutputFormat::Gltf)
        export_gltf(mesh, path, options);
    else
        save_export_mesh(export_mesh(mesh, options), path, format, options.msh);
    options.progress.done();  // the other formats are written in one piece: no progress before the end
}

}  // namespace rgbio
