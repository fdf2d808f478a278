#pragma once
// A vertex of a level with its one-ring in order and the crease tags of its edges: all that the
// closed forms of docs/loop-creases.md read.
#include <vector>

#include <glm/vec3.hpp>

#include "crease_tags.h"
#include "osd_far.h"

namespace osdoracle {

struct Neighbourhood {
    glm::dvec3 centre{0.0};
    // Neighbours in fan order: the triangles around the centre are (centre, ring[i], ring[i+1]), the
    // last one wrapping around to ring[0] for an interior vertex. A boundary vertex's ring starts and
    // ends on its two boundary edges.
    std::vector<glm::dvec3> ring;
    std::vector<int> ring_vertices;     // indices in the level, parallel to ring
    std::vector<double> edge_sharpness; // of the edge (centre, ring[i])
    double vertex_sharpness = 0.0;
    bool boundary = false;
};

// Throws std::logic_error if the vertex's triangles do not form one fan.
Neighbourhood gather_neighbourhood(const FarLevel& level, const LevelTags& tags, int vertex);

// The triangles around each vertex of a level, to gather many neighbourhoods at once.
std::vector<std::vector<int>> triangles_around_vertices(const FarLevel& level);
Neighbourhood gather_neighbourhood(const FarLevel& level, const LevelTags& tags, int vertex,
                                   const std::vector<int>& triangles_around);

}  // namespace osdoracle
