#pragma once
// The topology of a triangle mesh as its indices give it (vertices that merely share a position stay
// apart), component by component: counts, Euler characteristic, boundary loops, whether it is an
// oriented manifold, the fewest triangles a mesh of that topology can have, and why two meshes differ.
// The cage (cage.h) keeps it; plain data in and out.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "rgb/mesh/base_mesh.h"

namespace rgbdetail {

// One connected component (faces joined through shared vertex indices).
struct ComponentTopology {
    std::size_t vertices = 0;        // vertices used by the component's faces
    std::size_t edges = 0;
    std::size_t faces = 0;
    std::size_t boundary_loops = 0;
    long euler = 0;                  // vertices - edges + faces
    std::uint32_t first_vertex = 0;  // the component's smallest vertex index (ties in the order)
    double area = 0.0;

    // 2 - 2g - b = χ for an orientable surface.
    long genus() const { return (2 - euler - static_cast<long>(boundary_loops)) / 2; }
};

// The components in a canonical order: by Euler characteristic, then boundary loops (ascending),
// then faces (descending), then first vertex. Two meshes have the same topology when the sequences
// of (euler, boundary_loops) agree; unused vertices belong to no component.
struct MeshTopology {
    std::vector<ComponentTopology> components;
};

// Why the triangles are not an oriented 2-manifold triangle mesh over vertex_count vertices (an index
// out of range, a repeated corner, a directed edge used twice, an edge in three faces, two faces on
// the same three vertices, a vertex whose faces form more than one fan), or nothing.
std::optional<std::string> manifold_problem(std::size_t vertex_count, std::span<const rgb::Triangle> triangles);

// Throws std::invalid_argument with manifold_problem's reason when the mesh is not an oriented
// manifold.
MeshTopology topology_of(std::span<const glm::dvec3> positions, std::span<const rgb::Triangle> triangles);

// The fewest triangles a manifold triangle mesh (a simplicial surface: no two faces on the same
// corners, no two edges between the same vertices) of genus g with b boundary loops can have; the
// derivation is in mesh_topology.cpp. 4 for a sphere, 1 for a disc, 6 for an annulus, 14 for a torus, 8 for
// a torus with one hole, 24 for genus 2.
std::size_t smallest_component_triangles(long genus, std::size_t boundary_loops);
// The sum over the components.
std::size_t smallest_cage_triangles(const MeshTopology& topology);

// A user-readable reason why a cage of topology c cannot stand for a mesh of topology m, or nothing.
std::optional<std::string> topology_mismatch(const MeshTopology& m, const MeshTopology& c);

// A component's faces, its topology and its share of the target.
struct ComponentPart {
    std::vector<std::uint32_t> faces;
    ComponentTopology topology;
    std::size_t smallest = 0;
    std::size_t share = 0;
};

// Faces grouped by component (through shared vertex indices), components in order of first face,
// each with its topology; the mesh must be a valid oriented manifold (manifold_problem).
std::vector<ComponentPart> split_components(std::span<const glm::dvec3> positions, std::span<const rgb::Triangle> triangles);
// MeshTopology's canonical order of components.
bool canonical_before(const ComponentTopology& a, const ComponentTopology& b);
// "genus G with B boundary loops (Euler characteristic X)", for messages.
std::string describe(const ComponentTopology& c);
// The area of a triangle, given by its corners or by indices into positions.
double triangle_area(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);
double triangle_area(std::span<const glm::dvec3> positions, const rgb::Triangle& t);

}  // namespace rgbdetail
