// The level-of-detail requests shared by the brush, the CLI and the tests (spec §3.1, §3.2).
#include <algorithm>
#include <vector>

#include "rgb/loop_geometry.h"
#include "rgb/mesh.h"
#include "rgb/operators.h"
#include "rgb/refine.h"

namespace rgb {

namespace {

// Collects what the operators do while it is alive.
class EditLog : public MeshObserver {
public:
    explicit EditLog(Mesh& mesh) : mesh_(mesh) { mesh_.add_observer(this); }
    ~EditLog() override { mesh_.remove_observer(this); }
    EditLog(const EditLog&) = delete;
    EditLog& operator=(const EditLog&) = delete;

    void vertex_added(const Mesh&, VertexId, VertexId, VertexId) override { ++stats.splits; }
    void vertex_removed(const Mesh&, VertexId) override { ++stats.removals; }
    void face_added(const Mesh&, FaceId f) override { added.push_back(f); }

    std::vector<FaceId> added;
    SetLevelStats stats;

private:
    Mesh& mesh_;
};

int face_target(const Mesh& mesh, FaceId f, const std::function<int(const glm::dvec3&)>& target_at) {
    int t = -1;
    for (VertexId v : mesh.face_vertices(f)) t = std::max(t, target_at(displayed_position(mesh, v)));
    return t;
}

void refine_towards_targets(Mesh& mesh, std::vector<FaceId> work, EditLog& log,
                            const std::function<int(const glm::dvec3&)>& target_at) {
    while (!work.empty()) {
        const FaceId f = work.back();
        work.pop_back();
        if (!mesh.is_live(f) || mesh.level(f) >= face_target(mesh, f, target_at)) continue;
        const HalfedgeId h = edge_refining_face(mesh, f);
        log.added.clear();
        refine_edge(mesh, mesh.from_vertex(h), mesh.to_vertex(h));
        work.insert(work.end(), log.added.begin(), log.added.end());
    }
}

// Appends the faces the removals create to `created`.
void coarsen_towards_targets(Mesh& mesh, std::span<const FaceId> seeds, EditLog& log,
                             const std::function<int(const glm::dvec3&)>& target_at, std::vector<FaceId>& created) {
    std::vector<VertexId> candidates;
    auto gather = [&](std::span<const FaceId> faces) {
        for (FaceId f : faces)
            if (mesh.is_live(f))
                for (VertexId v : mesh.face_vertices(f))
                    if (mesh.level(v) > 0) candidates.push_back(v);
    };
    gather(seeds);
    // Finer vertices first: removing them is what makes the coarser ones removable.
    bool removed_any = true;
    while (removed_any) {
        removed_any = false;
        std::sort(candidates.begin(), candidates.end());
        candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
        std::stable_sort(candidates.begin(), candidates.end(),
                         [&](VertexId a, VertexId b) { return mesh.level(a) > mesh.level(b); });
        std::vector<VertexId> pass;
        pass.swap(candidates);
        for (VertexId v : pass) {
            if (!mesh.is_live(v)) continue;
            const int target = target_at(displayed_position(mesh, v));
            if (target < 0 || mesh.level(v) <= target) continue;
            if (!can_remove_vertex(mesh, v)) {
                candidates.push_back(v);
                continue;
            }
            log.added.clear();
            remove_vertex(mesh, v);
            removed_any = true;
            gather(log.added);
            created.insert(created.end(), log.added.begin(), log.added.end());
        }
        std::erase_if(candidates, [&](VertexId v) { return !mesh.is_live(v); });
    }
}

}  // namespace

Region Region::everywhere() {
    return Region{[](const glm::dvec3&) { return true; }};
}

Region Region::sphere(const glm::dvec3& centre, double radius) {
    return Region{[centre, r2 = radius * radius](const glm::dvec3& p) {
        const glm::dvec3 d = p - centre;
        return d.x * d.x + d.y * d.y + d.z * d.z <= r2;
    }};
}

SetLevelStats set_level_faces(Mesh& mesh, std::span<const FaceId> seeds,
                              const std::function<int(const glm::dvec3&)>& target_at, LodDirection direction) {
    EditLog log(mesh);
    // Seeds consumed by the coarsening are replaced by the faces it created.
    std::vector<FaceId> work(seeds.begin(), seeds.end());
    if (direction != LodDirection::Refine) coarsen_towards_targets(mesh, seeds, log, target_at, work);
    if (direction != LodDirection::Coarsen) refine_towards_targets(mesh, std::move(work), log, target_at);
    return log.stats;
}

SetLevelStats set_level(Mesh& mesh, const Region& region, int target, LodDirection direction) {
    std::vector<FaceId> seeds;
    for (FaceId f : mesh.faces()) {
        const auto& fv = mesh.face_vertices(f);
        if (std::any_of(fv.begin(), fv.end(), [&](VertexId v) { return region.contains(displayed_position(mesh, v)); }))
            seeds.push_back(f);
    }
    return set_level_faces(
        mesh, seeds, [&](const glm::dvec3& p) { return region.contains(p) ? target : -1; }, direction);
}

void refine_uniform(Mesh& mesh, int level) {
    // One level at a time: while going from level l to l+1 no triangle is coarser than l, so every
    // green edge of level l can be split at once, with no recursion and no extra refinement (the
    // rings of all coarser vertices exist).
    // Room for the final mesh at once, so that no level copies the arrays: a face of level k becomes
    // 4^(level - k) faces; an interior split adds one vertex per two faces, a boundary one (at most
    // 2^steps per boundary edge) one per face. Steps are capped so the shifts stay defined; a level
    // that high cannot be reached anyway.
    std::size_t new_faces = 0, new_boundary_vertices = 0;
    for (FaceId f : mesh.faces()) {
        const int steps = std::clamp(level - mesh.level(f), 0, 24);
        new_faces += (std::size_t(1) << (2 * steps)) - 1;
        for (int c = 0; c < 3; ++c)
            if (mesh.is_boundary(Mesh::halfedge(f, c))) new_boundary_vertices += (std::size_t(1) << steps) - 1;
    }
    mesh.reserve(mesh.face_capacity() + new_faces, mesh.vertex_capacity() + new_faces / 2 + new_boundary_vertices);
    std::vector<FaceId> front;
    for (int l = 0; l < level; ++l) {
        // Only a G_l or R_l triangle can have a green edge of level l.
        auto splittable_edge = [&](FaceId f) {
            const FaceType& t = mesh.type(f);
            if (!mesh.is_live(f) || t.level != l || t.colour == Colour::Blue) return HalfedgeId();
            for (int c = 0; c < 3; ++c) {
                const HalfedgeId h = Mesh::halfedge(f, c);
                const EdgeType e = mesh.edge_type(h);
                if (e.colour == Colour::Green && e.level == l) return h;
            }
            return HalfedgeId();
        };
        // Every face a split creates contains the new vertex; the new R_l ones (the only ones with an
        // edge left to split) go on a stack that is worked off before the sweep moves on. So the
        // refinement spreads from face to neighbour while their data is still in cache, and slots the
        // sweep has passed (reused ones) are not missed.
        for (std::uint32_t i = 0; i < mesh.face_capacity(); ++i) {
            front.push_back(FaceId(i));
            while (!front.empty()) {
                const FaceId f = front.back();
                front.pop_back();
                const HalfedgeId h = splittable_edge(f);
                if (!h.valid()) continue;
                front.push_back(f);
                const VertexId v = split_edge(mesh, h);
                const HalfedgeId start = mesh.vertex_halfedge(v);
                HalfedgeId o = start;
                do {
                    const FaceId g = Mesh::face(o);
                    if (mesh.colour(g) == Colour::Red && mesh.level(g) == l) front.push_back(g);
                    o = mesh.ccw_rotated(o);
                } while (o.valid() && o != start);
            }
        }
    }
}

}  // namespace rgb
