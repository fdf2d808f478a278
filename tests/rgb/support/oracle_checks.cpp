#include "support/oracle_checks.h"

#include <algorithm>
#include <sstream>

#include <glm/geometric.hpp>

#include "rgb/mesh/invariants.h"
#include "rgb/values/loop_geometry.h"
#include "support/triangle_keys.h"

namespace rgbtest {
namespace {

std::string str(const glm::dvec3& p) {
    std::ostringstream s;
    s.precision(17);
    s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
    return s.str();
}

testing::AssertionResult position_agrees(const char* what, rgb::VertexId v, Identity id, int k, const glm::dvec3& got,
                                         const glm::dvec3& want, double tolerance) {
    const double error = glm::distance(got, want);
    if (error <= tolerance) return testing::AssertionSuccess();
    return testing::AssertionFailure() << what << " of vertex " << v.idx << " (identity " << id << ") at level " << k
                                       << " is " << str(got) << ", oracle " << str(want) << ", error " << error;
}

}  // namespace

double oracle_tolerance(const TestMesh& base) { return 1e-12 * bounding_box_diagonal(base.positions); }

testing::AssertionResult invariants_hold(const rgb::Mesh& mesh) {
    const rgb::InvariantReport report = rgb::check_invariants(mesh);
    if (report.ok()) return testing::AssertionSuccess();
    testing::AssertionResult failure = testing::AssertionFailure();
    for (const std::string& line : report.violations) failure << "\n  " << line;
    return failure;
}

testing::AssertionResult vertex_agrees(const OracleView& view, rgb::VertexId v) {
    const Identity id = view.ids.identity(v);
    const UniformLoopOracle& oracle = view.ids.oracle();
    if (id == IdentityTracker::kNone) return testing::AssertionFailure() << "vertex " << v.idx << " has no identity";
    const int own = view.mesh.level(v);
    if (auto r = position_agrees("insertion position", v, id, own, view.mesh.insertion_position(v),
                                 oracle.position(own, id), view.tolerance);
        !r)
        return r;
    const int k = rgb::display_level(view.mesh, v);
    if (k > oracle.levels())
        return testing::AssertionFailure() << "vertex " << v.idx << " displayed at level " << k << " beyond the oracle";
    return position_agrees("displayed position", v, id, k, rgb::displayed_position(view.mesh, v), oracle.position(k, id),
                           view.tolerance);
}

testing::AssertionResult face_agrees(const OracleView& view, rgb::FaceId f) {
    if (view.mesh.colour(f) != rgb::Colour::Green) return testing::AssertionSuccess();
    const int l = view.mesh.level(f);
    const IdentityTriangle t = view.ids.identity_triangle(f);
    if (l <= view.ids.oracle().levels() && view.ids.oracle().has_face(l, t)) return testing::AssertionSuccess();
    const auto& v = view.mesh.face_vertices(f);
    return testing::AssertionFailure() << "green face " << f.idx << " (" << v[0].idx << ", " << v[1].idx << ", "
                                       << v[2].idx << ") of level " << l << " = identities (" << t[0] << ", " << t[1]
                                       << ", " << t[2] << ") is not a face of the uniform mesh of that level";
}

testing::AssertionResult everything_agrees(const OracleView& view) {
    for (rgb::VertexId v : view.mesh.vertices())
        if (auto r = vertex_agrees(view, v); !r) return r;
    for (rgb::FaceId f : view.mesh.faces())
        if (auto r = face_agrees(view, f); !r) return r;
    return testing::AssertionSuccess();
}

testing::AssertionResult equals_uniform(const OracleView& view, int k) {
    const UniformLoopOracle& oracle = view.ids.oracle();
    if (view.mesh.num_vertices() != oracle.num_identities(k))
        return testing::AssertionFailure() << view.mesh.num_vertices() << " vertices, uniform level " << k << " has "
                                           << oracle.num_identities(k);
    std::vector<bool> seen(oracle.num_identities(k), false);
    for (rgb::VertexId v : view.mesh.vertices()) {
        const Identity id = view.ids.identity(v);
        if (id >= seen.size() || seen[id])
            return testing::AssertionFailure() << "vertex " << v.idx << " has identity " << id
                                               << ", outside the uniform level or repeated";
        seen[id] = true;
        if (rgb::display_level(view.mesh, v) != k)
            return testing::AssertionFailure() << "vertex " << v.idx << " displayed at level "
                                               << rgb::display_level(view.mesh, v) << ", not " << k;
        if (auto r = position_agrees("displayed position", v, id, k, rgb::displayed_position(view.mesh, v),
                                     oracle.position(k, id), view.tolerance);
            !r)
            return r;
    }
    std::vector<IdentityTriangle> faces;
    for (rgb::FaceId f : view.mesh.faces()) {
        if (view.mesh.colour(f) != rgb::Colour::Green || view.mesh.level(f) != k)
            return testing::AssertionFailure() << "face " << f.idx << " is " << rgb::colour_name(view.mesh.colour(f))
                                               << " of level " << view.mesh.level(f) << ", not green of level " << k;
        faces.push_back(canonical_rotation(view.ids.identity_triangle(f)));
    }
    std::sort(faces.begin(), faces.end());
    if (faces != oracle.faces(k)) {
        std::vector<IdentityTriangle> missing;
        std::set_difference(oracle.faces(k).begin(), oracle.faces(k).end(), faces.begin(), faces.end(),
                            std::back_inserter(missing));
        testing::AssertionResult failure = testing::AssertionFailure();
        failure << "faces differ from uniform level " << k << "; " << missing.size() << " oracle faces missing";
        if (!missing.empty()) failure << ", e.g. (" << missing[0][0] << ", " << missing[0][1] << ", " << missing[0][2] << ")";
        return failure;
    }
    return testing::AssertionSuccess();
}

testing::AssertionResult equals_base(const rgb::Mesh& mesh, const TestMesh& base) {
    if (mesh.num_vertices() != base.positions.size() || mesh.num_faces() != base.triangles.size())
        return testing::AssertionFailure() << mesh.num_vertices() << " vertices and " << mesh.num_faces()
                                           << " faces; the base mesh has " << base.positions.size() << " and "
                                           << base.triangles.size();
    for (std::uint32_t i = 0; i < base.positions.size(); ++i) {
        const rgb::VertexId v(i);
        if (!mesh.is_live(v) || mesh.level(v) != 0)
            return testing::AssertionFailure() << "base vertex " << i << " is not a live level-0 vertex";
        if (rgb::displayed_position(mesh, v) != base.positions[i] || mesh.insertion_position(v) != base.positions[i])
            return testing::AssertionFailure() << "base vertex " << i << " is at "
                                               << str(rgb::displayed_position(mesh, v)) << ", base "
                                               << str(base.positions[i]);
    }
    std::vector<rgb::Triangle> faces, want;
    for (rgb::FaceId f : mesh.faces()) {
        if (mesh.colour(f) != rgb::Colour::Green || mesh.level(f) != 0)
            return testing::AssertionFailure() << "face " << f.idx << " is not green of level 0";
        const auto& v = mesh.face_vertices(f);
        faces.push_back(canonical_rotation(rgb::Triangle{v[0].idx, v[1].idx, v[2].idx}));
    }
    for (const rgb::Triangle& t : base.triangles) want.push_back(canonical_rotation(t));
    std::sort(faces.begin(), faces.end());
    std::sort(want.begin(), want.end());
    if (faces != want) return testing::AssertionFailure() << "faces differ from the base mesh";
    return testing::AssertionSuccess();
}

}  // namespace rgbtest
