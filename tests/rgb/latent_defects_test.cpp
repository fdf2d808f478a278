// Defects the first version carried without a test noticing: a halfedge search from a removed
// vertex, a "pillow" base mesh, and the observer event order the operators promise (observer.h).
#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rgb/lod/refine.h"
#include "rgb/mesh/mesh.h"
#include "rgb/mesh/observer.h"
#include "rgb/mesh/operators.h"
#include "rgb/values/loop_split.h"
#include "support/test_meshes.h"

namespace rgbtest {
namespace {

TEST(LatentDefects, NoHalfedgeLeadsFromOrToARemovedVertex) {
    rgb::Mesh mesh = make_rgb_mesh(icosahedron());
    const rgb::VertexId a(0), b = mesh.to_vertex(mesh.vertex_halfedge(a));
    const rgb::VertexId v = rgb::split_edge(mesh, mesh.find_edge(a, b));
    const rgb::VertexId neighbour = mesh.to_vertex(mesh.vertex_halfedge(v));
    rgb::remove_vertex(mesh, v);
    ASSERT_FALSE(mesh.is_live(v));
    // Its slot still holds stale links; the search must not follow them (it used to circle forever).
    EXPECT_FALSE(mesh.find_halfedge(v, neighbour).valid());
    EXPECT_FALSE(mesh.find_halfedge(neighbour, v).valid());
    EXPECT_FALSE(mesh.find_edge(v, a).valid());
    EXPECT_TRUE(mesh.find_edge(a, b).valid());
}

TEST(LatentDefects, APillowIsRefusedWithTheTrianglesNamed) {
    const std::vector<glm::dvec3> positions{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    try {
        rgb::Mesh mesh(positions, std::vector<rgb::Triangle>{{0, 1, 2}, {0, 2, 1}});
        FAIL() << "a pillow was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()), "triangles 0 and 1 use the same three vertices");
    }
}

// Records each operator's events as letters: F face removed, V vertex removed, a vertex added,
// f face added; and checks that each element is readable when its event says it is.
class EventRecorder : public rgb::MeshObserver {
public:
    explicit EventRecorder(rgb::Mesh& mesh) : mesh_(mesh) { mesh_.add_observer(this); }
    ~EventRecorder() override { mesh_.remove_observer(this); }
    EventRecorder(const EventRecorder&) = delete;
    EventRecorder& operator=(const EventRecorder&) = delete;

    void face_removed(const rgb::Mesh& m, rgb::FaceId f) override {
        events += 'F';
        readable = readable && m.is_live(f) && corners_live(m, f);
    }
    void vertex_removed(const rgb::Mesh& m, rgb::VertexId v) override {
        events += 'V';
        readable = readable && m.is_live(v);
    }
    void vertex_added(const rgb::Mesh& m, rgb::VertexId v, rgb::VertexId a, rgb::VertexId b) override {
        events += 'a';
        readable = readable && m.is_live(v) && m.is_live(a) && m.is_live(b);
    }
    void face_added(const rgb::Mesh& m, rgb::FaceId f) override {
        events += 'f';
        readable = readable && m.is_live(f) && corners_live(m, f);
    }

    std::string events;
    bool readable = true;

private:
    static bool corners_live(const rgb::Mesh& m, rgb::FaceId f) {
        for (rgb::VertexId v : m.face_vertices(f))
            if (!m.is_live(v)) return false;
        return true;
    }
    rgb::Mesh& mesh_;
};

// The events as blocks "F+ [mark] f+" (faces removed, at most one vertex event, faces added): the
// vertex events of the blocks in order ('-' for none), or "" if the events are not such blocks.
// (Written out rather than with std::regex, which g++ 12 warns about under the sanitizers.)
std::string block_marks(const std::string& events) {
    std::string marks;
    std::size_t i = 0;
    while (i < events.size()) {
        const std::size_t removed = events.find_first_not_of('F', i);
        if (removed == i || removed == std::string::npos) return "";
        i = removed;
        char mark = '-';
        if (events[i] == 'a' || events[i] == 'V') mark = events[i++];
        const std::size_t added = events.find_first_not_of('f', i);
        if (added == i) return "";
        i = added == std::string::npos ? events.size() : added;
        marks += mark;
    }
    return marks;
}

// Random splits and removals: a split (with the swaps it folds in) reports one block in the promised
// order; a removal may swap first, as blocks of their own, then merges in one block.
TEST(LatentDefects, OperatorsReportTheirEventsInThePromisedOrder) {
    auto is_split_block = [](const std::string& events) { return block_marks(events) == "a"; };
    auto is_removal_blocks = [](const std::string& events) {
        const std::string marks = block_marks(events);
        return std::count(marks.begin(), marks.end(), 'V') == 1 && std::count(marks.begin(), marks.end(), '-') + 1 == std::ssize(marks);
    };
    for (const TestMesh& base : {icosahedron(), fan(6), grid(3, 3)}) {
        rgb::Mesh mesh = make_rgb_mesh(base);
        std::mt19937 rng(5);
        std::size_t splits = 0, removals = 0;
        for (int step = 0; step < 400; ++step) {
            EventRecorder recorder(mesh);
            std::vector<rgb::FaceId> faces;
            for (rgb::FaceId g : mesh.faces()) faces.push_back(g);
            const rgb::FaceId f = faces[rng() % faces.size()];
            const rgb::HalfedgeId h = rgb::Mesh::halfedge(f, static_cast<int>(rng() % 3));
            const rgb::VertexId v = mesh.face_vertices(f)[rng() % 3];
            if (rng() % 3 != 0 && rgb::can_split_edge(mesh, h) && mesh.edge_type(h).level < 5) {
                rgb::split_edge(mesh, h);
                EXPECT_TRUE(is_split_block(recorder.events)) << base.name << " split: " << recorder.events;
                ++splits;
            } else if (mesh.level(v) > 0 && rgb::can_remove_vertex(mesh, v)) {
                rgb::remove_vertex(mesh, v);
                EXPECT_TRUE(is_removal_blocks(recorder.events)) << base.name << " removal: " << recorder.events;
                ++removals;
            }
            EXPECT_TRUE(recorder.readable) << base.name << " step " << step;
        }
        EXPECT_GT(splits, 50u) << base.name;
        EXPECT_GT(removals, 10u) << base.name;
    }
}

}  // namespace
}  // namespace rgbtest
