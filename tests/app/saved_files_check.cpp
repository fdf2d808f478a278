// Checks the files the Xvfb test saved from the real editor window (editor_window_test.sh):
//   saved_files_check ORIGINAL PAINTED UNDONE REDONE X0 Y0 X1 Y1
// Each saved file must load as a valid adaptive state; painting must have added triangles near the
// stroke from pixel (X0,Y0) to (X1,Y1) of the 1280x800 window; undo must restore the original
// triangle count exactly, and redo the painted mesh bit for bit.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "app/editor.h"
#include "io/mesh_file.h"
#include "rgb/invariants.h"
#include "rgb/state.h"
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

}  // namespace

int main(int argc, char** argv) {
    if (argc != 9) {
        std::fprintf(stderr, "usage: saved_files_check ORIGINAL PAINTED UNDONE REDONE X0 Y0 X1 Y1\n");
        return 2;
    }
    // The stroke's surface points, seen by an editor framing the original mesh like the window did.
    app::Editor editor({1280, 800});
    editor.set_covered_right(app::kPanelCover);
    if (!editor.open(argv[1])) {
        std::fprintf(stderr, "%s\n", editor.message().c_str());
        return 2;
    }
    const glm::vec2 from(std::atof(argv[5]), std::atof(argv[6])), to(std::atof(argv[7]), std::atof(argv[8]));
    std::vector<glm::dvec3> path;
    for (int i = 0; i <= 20; ++i) {
        editor.mouse_moved(from + (to - from) * (static_cast<float>(i) / 20.0f));
        if (auto hit = editor.cursor_hit()) path.push_back(hit->point);
    }
    expect(path.size() == 21, "the stroke crosses the surface (" + std::to_string(path.size()) + " of 21 points)");
    const double radius = path.empty() ? 0.0 : editor.brush_world_radius(path.front());
    const rgb::Mesh& original = editor.document().mesh();

    const rgb::Mesh painted = load_valid(argv[2]);
    const rgb::Mesh undone = load_valid(argv[3]);
    const rgb::Mesh redone = load_valid(argv[4]);
    const std::size_t before = app::test::faces_near(original, path, radius);
    const std::size_t after = app::test::faces_near(painted, path, radius);
    expect(after > before, "more triangles near the stroke (" + std::to_string(before) + " -> " + std::to_string(after) + ")");
    const testing::AssertionResult undo_ok = rgbtest::same_mesh(undone, original);
    expect(undo_ok, std::string("undo restores the original mesh exactly") + (undo_ok ? "" : ": " + std::string(undo_ok.message())));
    const testing::AssertionResult redo_ok = rgbtest::same_mesh(redone, painted);
    expect(redo_ok, std::string("redo restores the painted mesh exactly") + (redo_ok ? "" : ": " + std::string(redo_ok.message())));
    return failures == 0 ? 0 : 1;
}
