#pragma once
// How large a mesh a command may build: requests are estimated before they run
// (rgb::estimated_triangles, rgb::estimated_detail_triangles) and refused above this limit with a
// message, instead of ending in std::bad_alloc or the kernel's OOM killer halfway. The default
// follows the machine's memory and what a triangle costs on the path that builds it.
#include <cstddef>
#include <stdexcept>
#include <string>

namespace rgb {
class Mesh;
struct LevelRequest;
struct DetailRequest;
}  // namespace rgb

namespace rgbio {

// The paths that build or read a mesh, each with its own peak memory per triangle.
enum class MemoryUse {
    Level,      // refine --level, level and dab lines: the mesh, its addresses, the saved text
    MaxEdge,    // --max-edge: the LOD driver's queue besides
    Tolerance,  // --tolerance: the criterion's cache of every triangle's samples besides
    ScreenLod,  // render --screen-lod: the driver, and the render copy
    Budget,     // an apply budget line: the LOD driver from a uniform start
    Load,       // loading a saved file: the state's records and the mesh rebuilt from them
    Remesh,     // remesh, per point of the detail it samples
    Editor,     // the editor: the document's mesh, its display geometry, picking index and GL copies
};

// Peak bytes per triangle on each path, measured as whole processes by tests/bench/memory_bench.cpp
// (docs/benchmarks.md, "Memory per triangle"), with a margin.
std::size_t bytes_per_triangle(MemoryUse use);

// The default --max-triangles of a path: three quarters of the machine's physical memory over what
// a triangle costs there; for a path that saves a mesh, over what loading it back costs if that is
// more, so that whatever a command saves under its default limit loads again on the same machine.
std::size_t default_triangle_limit(MemoryUse use);

// The editor's limit for work on a path: what a triangle costs the editor that holds it, or the
// path's own cost if that is more.
std::size_t editor_triangle_limit(MemoryUse use);

class TooLarge : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Throws TooLarge naming the estimate and the limit when the request would exceed it.
void check_request_size(const rgb::Mesh& mesh, const rgb::LevelRequest& request, std::size_t limit);
// The same for a detail request (max-edge, tolerance, view), from a lower estimate made before any
// work: a request refused here could not have fit; one that passes may still be stopped at the
// limit by the work itself.
void check_detail_size(const rgb::Mesh& mesh, const rgb::DetailRequest& request, std::size_t limit);
// The same for a triangle budget, which is its own estimate.
void check_budget_size(std::size_t budget, std::size_t limit);

}  // namespace rgbio
