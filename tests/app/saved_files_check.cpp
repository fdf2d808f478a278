// Checks the files the Xvfb test saved from the real editor window and made with `rgbsub apply`
// (editor_window_test.sh):
//   saved_files_check ORIGINAL PANEL PAINTED UNDONE REDONE REPLAYED HALVES X0 Y0 X1 Y1
// Each file must load as a valid adaptive state. A drag on the panel must have painted nothing;
// painting must have added triangles near the stroke from pixel (X0,Y0) to (X1,Y1) of the 1280x800
// window; undo must restore the original mesh exactly, and redo the painted mesh; the session's
// script replayed by `rgbsub apply`, whole or in two halves with a save and reload between, must
// give the painted mesh.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "app/editor.h"
#include "io/mesh_file.h"
#include "rgb/mesh/invariants.h"
#include "rgb/mesh/state.h"
#include "stroke_support.h"
#include "support/same_mesh.h"

namespace {

int failures = 0;

void expect(bool ok, const std::string& what) {
    std::printf("%s: %s\n", ok ? "ok" : "FAILED", what.c_str());
    failures += !ok;
}

rgb::Mesh load_valid(const char* path) {
    rgb::Mesh mesh = rgbio::load_mesh(path);
    const rgb::InvariantReport report = rgb::check_invariants(mesh);
    expect(report.ok(), std::string(path) + " is a valid RGB state" + (report.ok() ? "" : ": " + report.violations.front()));
    return mesh;
}

void same(const rgb::Mesh& a, const rgb::Mesh& b, const std::string& what) {
    const testing::AssertionResult result = rgbtest::same_mesh(a, b);
    expect(result, what + (result ? "" : ": " + std::string(result.message())));
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 12) {
        std::fprintf(stderr, "usage: saved_files_check ORIGINAL PANEL PAINTED UNDONE REDONE REPLAYED HALVES X0 Y0 X1 Y1\n");
        return 2;
    }
    // The stroke's surface points, seen by an editor framing the original mesh like the window did.
    app::Editor editor({1280, 800});
    editor.set_covered_right(app::kPanelCover);
    if (!editor.open(argv[1])) {
        std::fprintf(stderr, "%s\n", editor.message().c_str());
        return 2;
    }
    const glm::vec2 from(std::atof(argv[8]), std::atof(argv[9])), to(std::atof(argv[10]), std::atof(argv[11]));
    std::vector<glm::dvec3> path;
    for (int i = 0; i <= 20; ++i) {
        editor.mouse_moved(from + (to - from) * (static_cast<float>(i) / 20.0f));
        if (auto hit = editor.cursor_hit()) path.push_back(hit->point);
    }
    expect(path.size() == 21, "the stroke crosses the surface (" + std::to_string(path.size()) + " of 21 points)");
    const double radius = path.empty() ? 0.0 : editor.brush_world_radius(path.front());
    const rgb::Mesh& original = editor.document().mesh();

    const rgb::Mesh panel = load_valid(argv[2]);
    const rgb::Mesh painted = load_valid(argv[3]);
    const rgb::Mesh undone = load_valid(argv[4]);
    const rgb::Mesh redone = load_valid(argv[5]);
    const rgb::Mesh replayed = load_valid(argv[6]);
    const rgb::Mesh halves = load_valid(argv[7]);
    same(panel, original, "a drag on the panel paints nothing");
    const std::size_t before = app::test::faces_near(original, path, radius);
    const std::size_t after = app::test::faces_near(painted, path, radius);
    expect(after > before, "more triangles near the stroke (" + std::to_string(before) + " -> " + std::to_string(after) + ")");
    same(undone, original, "undo restores the original mesh exactly");
    same(redone, painted, "redo restores the painted mesh exactly");
    same(replayed, painted, "rgbsub apply replays the saved strokes to the painted mesh");
    same(halves, painted, "replaying them in two halves, saved and reloaded between, gives it too");
    return failures == 0 ? 0 : 1;
}
