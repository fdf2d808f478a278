#include "io/formats/format_writers.h"

#include "io/files/atomic_file.h"
#include "io/obj/number_format.h"

namespace rgbio {

namespace {

// One DataArray of per-cell (or per-point) values, a line of up to 8 values at a time.
template <class Value>
void write_vtu_array(AtomicFileWriter& file, const char* type, const char* name, std::size_t count, Value value) {
    std::string& out = file.buffer();
    out += std::string("<DataArray type=\"") + type + "\" Name=\"" + name + "\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < count; ++i) {
        value(out, i);
        if (i % 8 == 7 || i + 1 == count) out += '\n';
        file.flush_if_full();
    }
    out += "</DataArray>\n";
}

}  // namespace

void save_vtu(const ExportMesh& mesh, const std::string& path) {
    AtomicFileWriter file(path);
    std::string& out = file.buffer();
    const std::size_t n = mesh.positions.size(), m = mesh.triangles.size();
    out += "<?xml version=\"1.0\"?>\n<!-- written by rgbsub: rgb_colour 0 green, 1 red, 2 blue; quality: aspect ratio -->\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
           "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" + std::to_string(n) + "\" NumberOfCells=\"" + std::to_string(m) +
           "\">\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const glm::dvec3& p : mesh.positions) {
        for (int i = 0; i < 3; ++i) append_double(out, p[i]);
        out += '\n';
        file.flush_if_full();
    }
    out += "</DataArray>\n</Points>\n<Cells>\n";
    write_vtu_array(file, "Int64", "connectivity", m, [&](std::string& o, std::size_t t) {
        for (std::uint32_t v : mesh.triangles[t]) append_integer(o, v);
    });
    write_vtu_array(file, "Int64", "offsets", m, [](std::string& o, std::size_t t) { append_integer(o, 3 * (t + 1)); });
    write_vtu_array(file, "UInt8", "types", m, [](std::string& o, std::size_t) { o += " 5"; });  // VTK_TRIANGLE
    out += "</Cells>\n<CellData Scalars=\"level\">\n";
    write_vtu_array(file, "UInt8", "level", m, [&](std::string& o, std::size_t t) { append_integer(o, mesh.levels[t]); });
    write_vtu_array(file, "UInt8", "rgb_colour", m, [&](std::string& o, std::size_t t) { append_integer(o, mesh.rgb_colours[t]); });
    const std::vector<rgb::TriangleQuality> quality = triangle_qualities(mesh);
    write_vtu_array(file, "Float64", "quality", m, [&](std::string& o, std::size_t t) { append_double(o, quality[t].aspect_ratio); });
    write_vtu_array(file, "Float64", "min_angle", m, [&](std::string& o, std::size_t t) { append_double(o, quality[t].min_angle); });
    out += "</CellData>\n";
    if (!mesh.colours.empty()) {
        out += "<PointData>\n<DataArray type=\"Float64\" Name=\"colour\" NumberOfComponents=\"3\" format=\"ascii\">\n";
        for (const glm::dvec3& c : mesh.colours) {
            for (int i = 0; i < 3; ++i) append_double(out, c[i]);
            out += '\n';
            file.flush_if_full();
        }
        out += "</DataArray>\n</PointData>\n";
    }
    out += "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    file.commit();
}

}  // namespace rgbio
