// Checks the painted file the Xvfb test saved from the real editor window (editor_window_test.sh):
//   saved_files_check ORIGINAL PAINTED X0 Y0 X1 Y1
// It must load as a valid adaptive state, and painting must have added triangles near the stroke
// from pixel (X0,Y0) to (X1,Y1) of the 1280x800 window. (The script compares the undone and redone
// files with the opened and painted ones byte for byte.)
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "app/editor.h"
#include "io/mesh_file.h"
#include "rgb/invariants.h"
#include "stroke_support.h"

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
    if (argc != 7) {
        std::fprintf(stderr, "usage: saved_files_check ORIGINAL PAINTED X0 Y0 X1 Y1\n");
        return 2;
    }
    // The stroke's surface points, seen by an editor framing the original mesh like the window did.
    app::Editor editor({1280, 800});
    if (!editor.open(argv[1])) {
        std::fprintf(stderr, "%s\n", editor.message().c_str());
        return 2;
    }
    const glm::vec2 from(std::atof(argv[3]), std::atof(argv[4])), to(std::atof(argv[5]), std::atof(argv[6]));
    std::vector<glm::dvec3> path;
    for (int i = 0; i <= 20; ++i) {
        editor.mouse_moved(from + (to - from) * (static_cast<float>(i) / 20.0f));
        if (auto hit = editor.cursor_hit()) path.push_back(hit->point);
    }
    expect(path.size() == 21, "the stroke crosses the surface (" + std::to_string(path.size()) + " of 21 points)");
    const double radius = path.empty() ? 0.0 : editor.brush_world_radius(path.front());
    const rgb::Mesh& original = editor.document().mesh();

    const rgb::Mesh painted = load_valid(argv[2]);
    const std::size_t before = app::test::faces_near(original, path, radius);
    const std::size_t after = app::test::faces_near(painted, path, radius);
    expect(after > before, "more triangles near the stroke (" + std::to_string(before) + " -> " + std::to_string(after) + ")");
    return failures == 0 ? 0 : 1;
}
