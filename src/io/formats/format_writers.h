#pragma once
// Folder io/formats: includes io/obj, io/files and the core.
// Writers of an ExportMesh to the formats other tools read, each streamed through AtomicFileWriter
// (io/files/atomic_file.h): a refused or failed save throws SaveError and leaves the old file as it
// was. None of them keeps the adaptive state (only OBJ does).
//
//   PLY  binary little-endian: vertex x, y, z as doubles (bit for bit) and, when the mesh has vertex
//        colours, red, green, blue as bytes; faces as `vertex_indices` (uchar count, uint indices)
//        with the face properties `level` and `rgb_colour` (uchar: 0 green, 1 red, 2 blue).
//   STL  binary: 32-bit floats (STL has no doubles), each facet's normal from its float corners.
//   VTU  VTK XML UnstructuredGrid (ParaView), ASCII: points as Float64 in shortest round-trip decimals
//        (bit for bit), triangles (VTK type 5), cell data `level`, `rgb_colour`, `quality` (aspect
//        ratio) and `min_angle` (degrees), point data `colour` when the mesh has vertex colours.
//   MSH  Gmsh 4.1, ASCII or binary (MshEncoding): one surface entity, nodes as shortest round-trip
//        decimals or as doubles (bit for bit either way), 3-node triangles (type 2), and $ElementData
//        `level`, `rgb_colour`, `quality`, `min_angle` (in binary files all four as doubles).
#include <string>

#include "io/formats/export_mesh.h"
#include "io/formats/mesh_format.h"

namespace rgbio {

void save_ply(const ExportMesh& mesh, const std::string& path);
void save_stl(const ExportMesh& mesh, const std::string& path);
void save_vtu(const ExportMesh& mesh, const std::string& path);
void save_msh(const ExportMesh& mesh, const std::string& path, MshEncoding encoding = MshEncoding::Ascii);

// The writer of `format` (Ply, Stl, Vtu or Msh, the last in `msh`'s encoding; OBJ and glTF have
// writers of their own).
void save_export_mesh(const ExportMesh& mesh, const std::string& path, OutputFormat format, MshEncoding msh = MshEncoding::Ascii);

}  // namespace rgbio
