#include "osd_far.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>

namespace osdoracle {
namespace {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

// Far's primvar interface: a value that can be cleared and accumulated with a double weight, so that
// PrimvarRefinerReal<double> computes every stencil in double precision.
template <class Vec>
struct Primvar {
    Vec value{0.0};
    void Clear() { value = Vec(0.0); }
    void AddWithWeight(const Primvar& source, double weight) { value += weight * source.value; }
};

// Far reports problems through process-wide callbacks; they are collected here and turned into an
// exception once Far returns.
std::string& far_messages() {
    static thread_local std::string messages;
    return messages;
}

void record_far_error(Far::ErrorType, const char* message) { far_messages() += std::string(message) + "\n"; }
void record_far_warning(const char* message) { far_messages() += std::string(message) + "\n"; }

void throw_if_far_complained(const char* stage) {
    if (far_messages().empty()) return;
    std::string message = std::string("OpenSubdiv Far failed while ") + stage + ": " + far_messages();
    far_messages().clear();
    throw std::runtime_error(message);
}

void check_sharpness(double sharpness, const std::string& what) {
    if (!std::isfinite(sharpness) || sharpness < 0.0)
        throw std::invalid_argument(what + ": sharpness must be finite and >= 0, got " + std::to_string(sharpness));
}

// Far accepts much that our meshes never contain (polygons, non-manifold edges, dangling tags) and
// resolves it silently, so the oracle insists on what its callers assume.
void validate(const FarInput& in, int levels) {
    if (levels < 0 || levels > 10) throw std::invalid_argument("levels must be in 0..10, got " + std::to_string(levels));
    if (in.positions.empty() || in.triangles.empty()) throw std::invalid_argument("the mesh has no triangles");
    const int n = static_cast<int>(in.positions.size());
    std::map<std::pair<int, int>, int> directed;  // directed edge -> triangle
    for (std::size_t t = 0; t < in.triangles.size(); ++t) {
        const auto& tri = in.triangles[t];
        const std::string name = "triangle " + std::to_string(t);
        for (int v : tri)
            if (v < 0 || v >= n) throw std::invalid_argument(name + ": vertex " + std::to_string(v) + " out of range");
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0])
            throw std::invalid_argument(name + ": repeats a vertex");
        for (int i = 0; i < 3; ++i)
            if (!directed.emplace(std::pair{tri[i], tri[(i + 1) % 3]}, static_cast<int>(t)).second)
                throw std::invalid_argument(name + ": edge " + std::to_string(tri[i]) + "-" +
                                            std::to_string(tri[(i + 1) % 3]) +
                                            " is used twice in the same direction (non-manifold or misoriented)");
    }
    for (const SharpEdge& e : in.creases) {
        const std::string name = "crease " + std::to_string(e.a) + "-" + std::to_string(e.b);
        if (!directed.contains({e.a, e.b}) && !directed.contains({e.b, e.a}))
            throw std::invalid_argument(name + ": not an edge of the mesh");
        check_sharpness(e.sharpness, name);
    }
    for (const SharpVertex& c : in.corners) {
        const std::string name = "corner " + std::to_string(c.vertex);
        if (c.vertex < 0 || c.vertex >= n) throw std::invalid_argument(name + ": vertex out of range");
        check_sharpness(c.sharpness, name);
    }
    if (in.uv) {
        if (in.uv->corners.size() != in.triangles.size())
            throw std::invalid_argument("uv: " + std::to_string(in.uv->corners.size()) + " corner triples for " +
                                        std::to_string(in.triangles.size()) + " triangles");
        for (std::size_t t = 0; t < in.uv->corners.size(); ++t)
            for (int v : in.uv->corners[t])
                if (v < 0 || v >= static_cast<int>(in.uv->values.size()))
                    throw std::invalid_argument("uv of triangle " + std::to_string(t) + ": value " + std::to_string(v) +
                                                " out of range");
    }
}

Sdc::Options::FVarLinearInterpolation far_option(UvInterpolation u) {
    switch (u) {
    case UvInterpolation::none: return Sdc::Options::FVAR_LINEAR_NONE;
    case UvInterpolation::corners_only: return Sdc::Options::FVAR_LINEAR_CORNERS_ONLY;
    case UvInterpolation::corners_plus1: return Sdc::Options::FVAR_LINEAR_CORNERS_PLUS1;
    case UvInterpolation::corners_plus2: return Sdc::Options::FVAR_LINEAR_CORNERS_PLUS2;
    case UvInterpolation::boundaries: return Sdc::Options::FVAR_LINEAR_BOUNDARIES;
    case UvInterpolation::all: return Sdc::Options::FVAR_LINEAR_ALL;
    }
    throw std::invalid_argument("unknown UV interpolation");
}

VertexRule rule_of(Sdc::Crease::Rule r) {
    switch (r) {
    case Sdc::Crease::RULE_SMOOTH: return VertexRule::smooth;
    case Sdc::Crease::RULE_DART: return VertexRule::dart;
    case Sdc::Crease::RULE_CREASE: return VertexRule::crease;
    case Sdc::Crease::RULE_CORNER: return VertexRule::corner;
    case Sdc::Crease::RULE_UNKNOWN: break;
    }
    throw std::runtime_error("OpenSubdiv Far left a vertex without a subdivision rule");
}

std::unique_ptr<Far::TopologyRefiner> create_refiner(const FarInput& in) {
    const std::vector<int> vertices_per_face(in.triangles.size(), 3);
    std::vector<Far::Index> face_vertices, crease_pairs, corner_vertices, uv_corners;
    std::vector<float> crease_weights, corner_weights;
    for (const auto& t : in.triangles) face_vertices.insert(face_vertices.end(), t.begin(), t.end());
    // Far stores sharpness as float; the values we use (integers, 10) are exact in float.
    for (const SharpEdge& e : in.creases) {
        crease_pairs.insert(crease_pairs.end(), {e.a, e.b});
        crease_weights.push_back(static_cast<float>(e.sharpness));
    }
    for (const SharpVertex& c : in.corners) {
        corner_vertices.push_back(c.vertex);
        corner_weights.push_back(static_cast<float>(c.sharpness));
    }

    Far::TopologyDescriptor desc;
    desc.numVertices = static_cast<int>(in.positions.size());
    desc.numFaces = static_cast<int>(in.triangles.size());
    desc.numVertsPerFace = vertices_per_face.data();
    desc.vertIndicesPerFace = face_vertices.data();
    desc.numCreases = static_cast<int>(in.creases.size());
    desc.creaseVertexIndexPairs = crease_pairs.data();
    desc.creaseWeights = crease_weights.data();
    desc.numCorners = static_cast<int>(in.corners.size());
    desc.cornerVertexIndices = corner_vertices.data();
    desc.cornerWeights = corner_weights.data();

    Far::TopologyDescriptor::FVarChannel uv_channel;
    Sdc::Options options;
    options.SetCreasingMethod(Sdc::Options::CREASE_UNIFORM);
    options.SetVtxBoundaryInterpolation(in.boundary == BoundaryInterpolation::edge_only
                                            ? Sdc::Options::VTX_BOUNDARY_EDGE_ONLY
                                            : Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
    if (in.uv) {
        for (const auto& c : in.uv->corners) uv_corners.insert(uv_corners.end(), c.begin(), c.end());
        uv_channel.numValues = static_cast<int>(in.uv->values.size());
        uv_channel.valueIndices = uv_corners.data();
        desc.numFVarChannels = 1;
        desc.fvarChannels = &uv_channel;
        options.SetFVarLinearInterpolation(far_option(in.uv->interpolation));
    }

    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    std::unique_ptr<Far::TopologyRefiner> refiner(
        Factory::Create(desc, Factory::Options(Sdc::SCHEME_LOOP, options)));
    throw_if_far_complained("reading the base mesh");
    if (!refiner) throw std::runtime_error("OpenSubdiv Far refused the base mesh");
    const Far::TopologyLevel& base = refiner->GetLevel(0);
    for (int v = 0; v < base.GetNumVertices(); ++v)
        if (base.IsVertexNonManifold(v))
            throw std::invalid_argument("vertex " + std::to_string(v) + ": non-manifold (its faces form several fans)");
    return refiner;
}

// Topology, tags and origins of every level; positions and UVs are filled in afterwards.
std::vector<FarLevel> describe_levels(const Far::TopologyRefiner& refiner) {
    std::vector<FarLevel> levels(refiner.GetNumLevels());
    for (int k = 0; k < refiner.GetNumLevels(); ++k) {
        const Far::TopologyLevel& level = refiner.GetLevel(k);
        const bool has_children = k + 1 < refiner.GetNumLevels();
        FarLevel& out = levels[k];
        for (int f = 0; f < level.GetNumFaces(); ++f) {
            const auto fv = level.GetFaceVertices(f);
            out.triangles.push_back({fv[0], fv[1], fv[2]});
        }
        for (int e = 0; e < level.GetNumEdges(); ++e) {
            const auto ev = level.GetEdgeVertices(e);
            out.edges.push_back({ev[0], ev[1], level.GetEdgeSharpness(e), has_children ? level.GetEdgeChildVertex(e) : -1});
        }
        for (int v = 0; v < level.GetNumVertices(); ++v) {
            out.vertex_sharpness.push_back(level.GetVertexSharpness(v));
            out.rules.push_back(rule_of(level.GetVertexRule(v)));
            if (has_children) out.vertex_child.push_back(level.GetVertexChildVertex(v));
        }
        if (has_children) {
            FarLevel& child = levels[k + 1];
            child.origins.resize(refiner.GetLevel(k + 1).GetNumVertices());
            for (int v = 0; v < level.GetNumVertices(); ++v) child.origins.at(out.vertex_child[v]) = {false, v, -1};
            for (const FarEdge& e : out.edges) child.origins.at(e.child) = {true, e.a, e.b};
        }
    }
    return levels;
}

std::vector<std::array<int, 3>> uv_value_indices(const Far::TopologyLevel& level) {
    std::vector<std::array<int, 3>> corners;
    for (int f = 0; f < level.GetNumFaces(); ++f) {
        const auto fv = level.GetFaceFVarValues(f, 0);
        corners.push_back({fv[0], fv[1], fv[2]});
    }
    return corners;
}

template <class Vec>
std::vector<std::array<Vec, 3>> per_corner(const Far::TopologyLevel& level, const std::vector<Primvar<Vec>>& values) {
    std::vector<std::array<Vec, 3>> corners;
    for (const auto& c : uv_value_indices(level)) corners.push_back({values[c[0]].value, values[c[1]].value, values[c[2]].value});
    return corners;
}

}  // namespace

FarRefinement refine_uniform(const FarInput& input, int levels) {
    validate(input, levels);
    far_messages().clear();
    Far::SetErrorCallback(record_far_error);
    Far::SetWarningCallback(record_far_warning);

    std::unique_ptr<Far::TopologyRefiner> refiner = create_refiner(input);
    Far::TopologyRefiner::UniformOptions uniform(levels);
    uniform.fullTopologyInLastLevel = true;  // Limit needs the last level's vertex-edge relations
    refiner->RefineUniform(uniform);
    throw_if_far_complained("refining");

    FarRefinement result;
    result.levels = describe_levels(*refiner);
    const Far::PrimvarRefinerReal<double> primvars(*refiner);

    std::vector<Primvar<glm::dvec3>> positions;
    for (const glm::dvec3& p : input.positions) positions.push_back({p});
    std::vector<Primvar<glm::dvec2>> uvs;
    if (input.uv)
        for (const glm::dvec2& uv : input.uv->values) uvs.push_back({uv});
    for (int k = 0; k <= levels; ++k) {
        FarLevel& level = result.levels[k];
        if (k > 0) {
            // Far takes the destination by non-const reference, hence the named pointers.
            std::vector<Primvar<glm::dvec3>> finer(refiner->GetLevel(k).GetNumVertices());
            Primvar<glm::dvec3>* finer_data = finer.data();
            primvars.Interpolate(k, positions.data(), finer_data);
            positions = std::move(finer);
            if (input.uv) {
                std::vector<Primvar<glm::dvec2>> finer_uvs(refiner->GetLevel(k).GetNumFVarValues(0));
                Primvar<glm::dvec2>* finer_uvs_data = finer_uvs.data();
                primvars.InterpolateFaceVarying(k, uvs.data(), finer_uvs_data, 0);
                uvs = std::move(finer_uvs);
            }
        }
        for (const auto& p : positions) level.positions.push_back(p.value);
        if (input.uv) {
            level.uv = per_corner(refiner->GetLevel(k), uvs);
            level.uv_value_index = uv_value_indices(refiner->GetLevel(k));
        }
    }

    std::vector<Primvar<glm::dvec3>> limit(positions.size());
    Primvar<glm::dvec3>* limit_data = limit.data();
    primvars.Limit(positions.data(), limit_data);
    for (const auto& p : limit) result.limit_positions.push_back(p.value);
    if (input.uv) {
        std::vector<Primvar<glm::dvec2>> limit_uvs(uvs.size());
        Primvar<glm::dvec2>* limit_uvs_data = limit_uvs.data();
        primvars.LimitFaceVarying(uvs.data(), limit_uvs_data, 0);
        result.limit_uv = per_corner(refiner->GetLevel(levels), limit_uvs);
    }
    throw_if_far_complained("interpolating");
    return result;
}

}  // namespace osdoracle
