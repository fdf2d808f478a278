#include "io/repair/loaded_mesh_assembly.h"

#include <algorithm>

#include "io/obj/printable_text.h"

namespace rgbio {

namespace {

std::string first_at(const SkippedLines& skipped) {
    return "the first on line " + std::to_string(skipped.first_line) + ": " + quoted_file_text(skipped.first_keyword);
}

std::vector<std::string> skipped_content_warnings(const ObjRecords& records) {
    std::vector<std::string> warnings;
    if (records.line_elements + records.point_elements > 0)
        warnings.push_back("ignored " + std::to_string(records.line_elements) + " line elements (l) and " +
                           std::to_string(records.point_elements) + " point elements (p): only faces form the surface");
    if (records.normals.count > 0)
        warnings.push_back("dropped " + std::to_string(records.normals.count) + " vertex normals (vn, the first on line " +
                           std::to_string(records.normals.first_line) +
                           "): they cannot be subdivided meaningfully (a refined surface bends between the input's vertices, so its normals "
                           "follow from its shape, not from the input's); --normals writes the exact normals of the limit surface instead");
    if (records.texcoord_w.count > 0)
        warnings.push_back("dropped the third texture coordinate (w) of " + std::to_string(records.texcoord_w.count) +
                           " vt lines (the first on line " + std::to_string(records.texcoord_w.first_line) + "): only u and v are kept");
    if (records.unsupported.count > 0)
        warnings.push_back("ignored " + std::to_string(records.unsupported.count) +
                           " OBJ statements rgbsub does not use (free-form geometry, display attributes; " +
                           first_at(records.unsupported) + ")");
    if (records.unknown.count > 0) {
        const std::string_view keyword = records.unknown.first_keyword;
        const bool upper = std::any_of(keyword.begin(), keyword.end(), [](char c) { return c >= 'A' && c <= 'Z'; });
        warnings.push_back("ignored " + std::to_string(records.unknown.count) + " lines with an unknown keyword (" +
                           first_at(records.unknown) + (upper ? "; OBJ keywords are lower case" : "") + ")");
    }
    return warnings;
}

// Keeps the vertices faces use, renumbered, and reports how many of the file's were unused.
void compact_vertices(ObjRecords& records, TriangleSoup& soup, LoadedMesh& mesh) {
    std::vector<std::uint32_t> new_index(soup.vertex_origin.size(), kNoIndex);
    for (const rgb::Triangle& t : soup.triangles)
        for (std::uint32_t v : t) new_index[v] = 0;
    // Every vertex used, each the OBJ vertex of its own index (always so for a saved file): nothing
    // to renumber, and the positions are the file's as they are.
    std::uint32_t expected = 0;
    if (soup.vertex_origin.size() == records.positions.size() && std::find(new_index.begin(), new_index.end(), kNoIndex) == new_index.end() &&
        std::all_of(soup.vertex_origin.begin(), soup.vertex_origin.end(), [&expected](std::uint32_t origin) { return origin == expected++; })) {
        mesh.positions = std::move(records.positions);
        mesh.file_vertex = soup.vertex_origin;
        mesh.triangles = std::move(soup.triangles);
        return;
    }
    std::size_t unused = 0, first_line = 0;
    mesh.positions.reserve(new_index.size());
    for (std::size_t v = 0; v < new_index.size(); ++v) {
        if (new_index[v] == kNoIndex) {
            if (unused++ == 0) first_line = records.position_lines[soup.vertex_origin[v]];
            continue;
        }
        new_index[v] = static_cast<std::uint32_t>(mesh.positions.size());
        mesh.positions.push_back(records.positions[soup.vertex_origin[v]]);
        soup.vertex_origin[mesh.positions.size() - 1] = soup.vertex_origin[v];
    }
    soup.vertex_origin.resize(mesh.positions.size());
    mesh.file_vertex = soup.vertex_origin;
    for (rgb::Triangle& t : soup.triangles)
        for (std::uint32_t& v : t) v = new_index[v];
    mesh.triangles = std::move(soup.triangles);
    if (unused > 0)
        mesh.warnings.push_back("removed " + std::to_string(unused) + " vertices used by no face (the first on line " +
                                std::to_string(first_line) + ") and renumbered the rest");
}

// soup.vertex_origin: per mesh vertex, after compaction.
void attach_colours(const ObjRecords& records, const TriangleSoup& soup, LoadedMesh& mesh) {
    if (records.colours.empty()) return;
    std::size_t colourless = 0, first_line = SIZE_MAX;
    for (std::uint32_t origin : soup.vertex_origin)
        if (!records.has_colour[origin]) {
            ++colourless;
            first_line = std::min(first_line, records.position_lines[origin]);
        }
    if (colourless > 0) {
        mesh.warnings.push_back("dropped the vertex colours: " + std::to_string(colourless) + " of the " +
                                std::to_string(soup.vertex_origin.size()) +
                                " vertices used by faces have none (the first on line " + std::to_string(first_line) +
                                "), and colours are kept only when every vertex has one");
        return;
    }
    mesh.colours.reserve(soup.vertex_origin.size());
    for (std::uint32_t origin : soup.vertex_origin) mesh.colours.push_back(records.colours[origin]);
}

void attach_texcoords(const ObjRecords& records, const TriangleSoup& soup, LoadedMesh& mesh) {
    if (soup.texcoords.empty()) return;
    std::vector<std::uint32_t> new_index(records.texcoords.size(), kNoIndex);
    for (const auto& corners : soup.texcoords)
        for (std::uint32_t uv : corners)
            if (uv != kNoIndex) new_index[uv] = 0;
    for (std::size_t uv = 0; uv < new_index.size(); ++uv) {
        if (new_index[uv] == kNoIndex) continue;
        new_index[uv] = static_cast<std::uint32_t>(mesh.texcoords.size());
        mesh.texcoords.push_back(records.texcoords[uv]);
    }
    mesh.triangle_texcoords = soup.texcoords;
    for (auto& corners : mesh.triangle_texcoords)
        for (std::uint32_t& uv : corners)
            if (uv != kNoIndex) uv = new_index[uv];
}

// Per triangle, the label its polygon carries; empty when no polygon has one.
template <class Value>
std::vector<Value> per_triangle(const ObjRecords& records, const TriangleSoup& soup, Value ObjPolygon::*field) {
    std::vector<Value> values;
    if (!records.polygons.has_labels(field)) return values;
    values.reserve(soup.polygons.size());
    for (std::uint32_t p : soup.polygons) values.push_back(records.polygons[p].*field);
    return values;
}

FaceLabels labels(const ObjRecords& records, const TriangleSoup& soup, const std::vector<std::string>& names,
                  std::uint32_t ObjPolygon::*field) {
    FaceLabels result;
    result.of_triangle = per_triangle(records, soup, field);
    if (!result.of_triangle.empty()) result.names = names;
    return result;
}

}  // namespace

LoadedMesh assemble_loaded_mesh(ObjRecords& records, TriangleSoup&& soup, std::vector<std::string>&& fixes) {
    LoadedMesh mesh;
    mesh.warnings = skipped_content_warnings(records);
    mesh.warnings.insert(mesh.warnings.end(), fixes.begin(), fixes.end());
    mesh.face_materials = labels(records, soup, records.material_names, &ObjPolygon::material);
    mesh.face_groups = labels(records, soup, records.group_names, &ObjPolygon::group);
    mesh.face_objects = labels(records, soup, records.object_names, &ObjPolygon::object);
    mesh.face_smoothing_groups = per_triangle(records, soup, &ObjPolygon::smoothing_group);
    mesh.material_libraries = records.material_libraries;
    attach_texcoords(records, soup, mesh);
    compact_vertices(records, soup, mesh);
    attach_colours(records, soup, mesh);
    return mesh;
}

}  // namespace rgbio
