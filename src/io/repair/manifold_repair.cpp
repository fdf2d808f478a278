#include "io/repair/manifold_repair.h"

#include <algorithm>

#include "io/obj/obj_error.h"
#include "io/repair/union_find.h"

namespace rgbio {

namespace {

constexpr std::size_t kMaxListedEdges = 5;  // non-manifold edges named in one message
constexpr std::size_t kMaxListedLines = 8;  // face lines named per edge

std::string count_of(std::size_t n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); }

class ManifoldRepair {
public:
    ManifoldRepair(TriangleSoup& soup, const std::vector<std::size_t>& position_lines, const std::string& file)
        : soup_(soup), tris_(soup.triangles), position_lines_(position_lines), file_(file) {}

    std::vector<EdgeUse> run(bool strict, std::vector<std::string>& warnings) {
        std::vector<EdgeUse> uses = edge_uses(tris_);
        std::size_t first_cut_line = SIZE_MAX;
        const std::size_t cut_edges = count_cut_edges(uses, &first_cut_line);
        if (strict && cut_edges > 0) throw_edge_error(uses);
        const BowTies bow_ties = find_bow_ties(uses);
        if (strict && bow_ties.vertices > 0) throw_bow_tie_error(bow_ties);
        if (cut_edges == 0 && bow_ties.vertices == 0) return uses;

        const std::size_t vertices_before = soup_.vertex_origin.size();
        split_fans(uses);
        for (uses = edge_uses(tris_); count_cut_edges(uses) > 0; uses = edge_uses(tris_)) {
            detach_cut_faces(uses);
            split_fans(edge_uses(tris_));
        }
        const std::size_t added = soup_.vertex_origin.size() - vertices_before;
        if (cut_edges > 0)
            warnings.push_back("cut " + count_of(cut_edges, "non-manifold edge", "non-manifold edges") +
                               " (shared by more than two faces) apart, the first at the face on line " +
                               std::to_string(first_cut_line) +
                               ": at each edge the first face in file order stays joined to the first one running the "
                               "other way, and the other faces got their own copies of the edge's vertices (" +
                               count_of(added - bow_ties.copies, "vertex", "vertices") + " added)");
        if (bow_ties.vertices > 0)
            warnings.push_back("split " + count_of(bow_ties.vertices, "non-manifold vertex", "non-manifold vertices") +
                               " (bow-ties: fans of faces that touch only at the vertex) into one vertex per fan (" +
                               count_of(bow_ties.copies, "vertex", "vertices") + " added), the first is vertex " +
                               obj_index(bow_ties.first) + " on line " + std::to_string(position_lines_[soup_.vertex_origin[bow_ties.first]]));
        return uses;
    }

private:
    struct BowTies {
        std::size_t vertices = 0, copies = 0;
        std::uint32_t first = 0;                   // the smallest bow-tie vertex id
        std::uint32_t first_fan_triangle = 0;      // its first triangle
        std::uint32_t second_fan_triangle = 0;     // the first triangle of its second fan
    };

    std::string obj_index(std::uint32_t v) const { return std::to_string(std::size_t(soup_.vertex_origin[v]) + 1); }

    // The two faces of the run uses[i, j) that stay joined (spec in manifold_repair.h).
    std::pair<std::size_t, std::size_t> kept_pair(const std::vector<EdgeUse>& uses, std::size_t i, std::size_t j) const {
        const std::uint32_t a = uses[i].a, b = uses[i].b;
        const bool first_direction = has_directed_edge(tris_[uses[i].triangle], a, b);
        for (std::size_t k = i + 1; k < j; ++k)
            if (has_directed_edge(tris_[uses[k].triangle], a, b) != first_direction) return {i, k};
        return {i, i + 1};
    }

    // Non-manifold edges; *first_line (if given) becomes the first line of a face cut off one.
    std::size_t count_cut_edges(const std::vector<EdgeUse>& uses, std::size_t* first_line = nullptr) const {
        std::size_t count = 0;
        for_each_edge(uses, [&](std::size_t i, std::size_t j) {
            if (j - i <= 2) return;
            ++count;
            if (!first_line) return;
            const auto [p, q] = kept_pair(uses, i, j);
            for (std::size_t k = i; k < j; ++k)
                if (k != p && k != q) *first_line = std::min(*first_line, soup_.lines[uses[k].triangle]);
        });
        return count;
    }

    // Unites the corners of t1 and t2 at both ends of their shared edge a-b.
    void join(UnionFind& corners, std::uint32_t t1, std::uint32_t t2, std::uint32_t a, std::uint32_t b) const {
        for (std::uint32_t v : {a, b}) corners.unite(3 * t1 + corner_of(tris_[t1], v), 3 * t2 + corner_of(tris_[t2], v));
    }

    // Fans of corners. join_all: across every edge, so separate fans touch only at their vertex;
    // otherwise across edges of two faces and the kept pair of each non-manifold edge.
    UnionFind corner_fans(const std::vector<EdgeUse>& uses, bool join_all) const {
        UnionFind corners(3 * tris_.size());
        for_each_edge(uses, [&](std::size_t i, std::size_t j) {
            if (j - i < 2) return;
            const std::uint32_t a = uses[i].a, b = uses[i].b;
            if (join_all) {
                for (std::size_t k = i + 1; k < j; ++k) join(corners, uses[i].triangle, uses[k].triangle, a, b);
                return;
            }
            const auto [p, q] = kept_pair(uses, i, j);
            join(corners, uses[p].triangle, uses[q].triangle, a, b);
        });
        return corners;
    }

    BowTies find_bow_ties(const std::vector<EdgeUse>& uses) const {
        UnionFind corners = corner_fans(uses, true);
        BowTies found;
        std::vector<std::uint32_t> first_root(soup_.vertex_origin.size(), UINT32_MAX);
        std::vector<std::uint8_t> root_seen(3 * tris_.size(), 0);
        std::vector<std::uint8_t> is_bow_tie(soup_.vertex_origin.size(), 0);
        for (std::uint32_t t = 0; t < tris_.size(); ++t)
            for (int i = 0; i < 3; ++i) {
                const std::uint32_t v = tris_[t][i];
                const std::uint32_t root = corners.find(3 * t + static_cast<std::uint32_t>(i));
                if (first_root[v] == UINT32_MAX) first_root[v] = root;
                if (root_seen[root]) continue;
                root_seen[root] = 1;
                if (root == first_root[v]) continue;
                ++found.copies;
                if (is_bow_tie[v]) continue;
                is_bow_tie[v] = 1;
                if (found.vertices++ == 0 || v < found.first) {
                    found.first = v;
                    found.second_fan_triangle = t;
                }
            }
        if (found.vertices > 0)
            found.first_fan_triangle = static_cast<std::uint32_t>(
                std::find_if(tris_.begin(), tris_.end(), [&](const rgb::Triangle& t) { return std::count(t.begin(), t.end(), found.first) > 0; }) -
                tris_.begin());
        return found;
    }

    // One vertex per fan: the fan of a vertex's first corner keeps it, later fans get copies.
    void split_fans(const std::vector<EdgeUse>& uses) {
        UnionFind corners = corner_fans(uses, false);
        std::vector<std::uint32_t> first_root(soup_.vertex_origin.size(), UINT32_MAX);
        std::vector<std::uint32_t> copy_of_root(3 * tris_.size(), kNoCopy);
        for (std::uint32_t t = 0; t < tris_.size(); ++t)
            for (int i = 0; i < 3; ++i) {
                std::uint32_t& v = tris_[t][i];
                const std::uint32_t root = corners.find(3 * t + static_cast<std::uint32_t>(i));
                if (first_root[v] == UINT32_MAX) first_root[v] = root;
                if (root == first_root[v]) continue;
                if (copy_of_root[root] == kNoCopy) copy_of_root[root] = soup_.copy_vertex(v);
                v = copy_of_root[root];
            }
    }

    // A cut face that still shares both vertices of a non-manifold edge takes its own copy of the
    // edge's smaller-id vertex.
    void detach_cut_faces(const std::vector<EdgeUse>& uses) {
        for_each_edge(uses, [&](std::size_t i, std::size_t j) {
            if (j - i <= 2) return;
            const auto [p, q] = kept_pair(uses, i, j);
            for (std::size_t k = i; k < j; ++k) {
                if (k == p || k == q) continue;
                rgb::Triangle& t = tris_[uses[k].triangle];
                t[corner_of(t, uses[i].a)] = soup_.copy_vertex(uses[i].a);
            }
        });
    }

    [[noreturn]] void throw_edge_error(const std::vector<EdgeUse>& uses) const {
        std::vector<std::string> listed;
        std::size_t count = 0, first_line = 0;
        for_each_edge(uses, [&](std::size_t i, std::size_t j) {
            if (j - i <= 2) return;
            if (count++ == 0) first_line = soup_.lines[uses[i].triangle];
            if (listed.size() == kMaxListedEdges) return;
            std::string entry = "edge " + obj_index(uses[i].a) + "-" + obj_index(uses[i].b) + " has " + std::to_string(j - i) + " faces (lines";
            // append() rather than " " + ...: GCC 12 warns falsely (-Wrestrict) about the latter here.
            for (std::size_t k = i; k < std::min(j, i + kMaxListedLines); ++k) entry.append(" ").append(std::to_string(soup_.lines[uses[k].triangle]));
            if (j - i > kMaxListedLines) entry += " and " + std::to_string(j - i - kMaxListedLines) + " more";
            listed.push_back(entry + ")");
        });
        std::string reason = std::to_string(count) + " non-manifold edge" + (count > 1 ? "s" : "") + " (more than two faces): ";
        for (std::size_t k = 0; k < listed.size(); ++k) reason += (k ? "; " : "") + listed[k];
        if (count > listed.size()) reason += "; ...";
        throw ObjError(ObjProblem::NonManifoldEdge, file_, first_line, reason);
    }

    [[noreturn]] void throw_bow_tie_error(const BowTies& bow_ties) const {
        const std::size_t first = soup_.lines[bow_ties.first_fan_triangle], second = soup_.lines[bow_ties.second_fan_triangle];
        const std::string faces = first == second ? "two parts of the face on line " + std::to_string(first)
                                                  : "the faces on lines " + std::to_string(first) + " and " + std::to_string(second);
        throw ObjError(ObjProblem::NonManifoldVertex, file_, position_lines_[soup_.vertex_origin[bow_ties.first]],
                       "non-manifold vertex " + obj_index(bow_ties.first) +
                           " (bow-tie): its faces form separate fans that touch only at this vertex (" + faces +
                           " are in different fans); without --strict rgbsub splits it into one vertex per fan");
    }

    static constexpr std::uint32_t kNoCopy = UINT32_MAX;
    TriangleSoup& soup_;
    std::vector<rgb::Triangle>& tris_;
    const std::vector<std::size_t>& position_lines_;
    const std::string& file_;
};

}  // namespace

std::vector<EdgeUse> make_manifold(TriangleSoup& soup, const std::vector<std::size_t>& position_lines, const std::string& file,
                                   bool strict, std::vector<std::string>& warnings) {
    return ManifoldRepair(soup, position_lines, file).run(strict, warnings);
}

}  // namespace rgbio
