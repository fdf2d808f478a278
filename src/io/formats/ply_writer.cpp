#include "io/formats/format_writers.h"

#include <stdexcept>

#include "io/files/atomic_file.h"

namespace rgbio {

void save_ply(const ExportMesh& mesh, const std::string& path) {
    AtomicFileWriter file(path);
    std::string& out = file.buffer();
    out += "ply\nformat binary_little_endian 1.0\ncomment written by rgbsub: face level and rgb_colour (0 green, 1 red, 2 blue)\n";
    out += "element vertex " + std::to_string(mesh.positions.size()) + "\nproperty double x\nproperty double y\nproperty double z\n";
    const bool colours = !mesh.colours.empty();
    if (colours) out += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    out += "element face " + std::to_string(mesh.triangles.size()) +
           "\nproperty list uchar uint vertex_indices\nproperty uchar level\nproperty uchar rgb_colour\nend_header\n";
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        for (int i = 0; i < 3; ++i) append_bytes(out, mesh.positions[v][i]);
        if (colours)
            for (int i = 0; i < 3; ++i) append_bytes(out, colour_byte(mesh.colours[v][i]));
        file.flush_if_full();
    }
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        append_bytes(out, std::uint8_t{3});
        for (std::uint32_t v : mesh.triangles[t]) append_bytes(out, v);
        append_bytes(out, mesh.levels[t]);
        append_bytes(out, mesh.rgb_colours[t]);
        file.flush_if_full();
    }
    file.commit();
}

void save_export_mesh(const ExportMesh& mesh, const std::string& path, OutputFormat format, MshEncoding msh) {
    switch (format) {
        case OutputFormat::Ply: return save_ply(mesh, path);
        case OutputFormat::Stl: return save_stl(mesh, path);
        case OutputFormat::Vtu: return save_vtu(mesh, path);
        case OutputFormat::Msh: return save_msh(mesh, path, msh);
        case OutputFormat::Obj:
        case OutputFormat::Gltf: break;
    }
    throw std::logic_error("save_export_mesh: OBJ and glTF have writers of their own");
}

}  // namespace rgbio
