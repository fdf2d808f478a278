// Brush benchmark: replays a recorded brush path (a wavy stroke across the view, one mouse sample
// per 5 px as a steady hand delivers them) through the editor's input layer on the bunny refined
// uniformly, and reports engine time per dab (set_level_faces) and picking time per dab, p50/p95.
// The radius shrinks with the level so the footprint stays near 2000 triangles: the claim under test
// is that a dab's cost follows its footprint, not the mesh size.
// Run on demand: ./brush_bench [levels...]   (default: 3 4, i.e. 235k and 940k triangles)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "app/editor.h"
#include "io/mesh_file.h"
#include "rgb/refine.h"

namespace {

constexpr glm::ivec2 kViewport{1280, 800};

struct Samples {
    std::vector<double> engine_ms, pick_ms, operations;
};

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(p * static_cast<double>(v.size() - 1))];
}

// The recorded path: left to right across the middle of the view, waving up and down.
std::vector<glm::vec2> recorded_path() {
    std::vector<glm::vec2> path;
    for (float x = 0.38f * kViewport.x; x <= 0.62f * kViewport.x; x += 5.0f)
        path.push_back({x, 0.55f * kViewport.y + 40.0f * std::sin(x / 40.0f)});
    return path;
}

Samples replay(app::Editor& editor, app::Modifiers mods) {
    Samples samples;
    const std::vector<glm::vec2> path = recorded_path();
    editor.mouse_moved(path.front());
    const auto press_start = std::chrono::steady_clock::now();
    editor.mouse_pressed(app::MouseButton::Left, mods);
    std::printf("    press (undo snapshot + first, whole-surface pick + dab) %.1f ms\n",
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - press_start).count());
    std::size_t dabs = editor.dab_timing().dabs;
    const auto record = [&] {
        if (editor.dab_timing().dabs == dabs) return;
        dabs = editor.dab_timing().dabs;
        samples.engine_ms.push_back(editor.dab_timing().last_ms);
        samples.pick_ms.push_back(editor.dab_timing().last_pick_ms);
        samples.operations.push_back(static_cast<double>(editor.dab_timing().last_operations));
    };
    record();
    for (const glm::vec2& p : path) {
        editor.mouse_moved(p);
        record();
    }
    editor.mouse_released(app::MouseButton::Left);
    return samples;
}

void report(const char* what, const Samples& s) {
    std::printf("  %-28s %4zu dabs  engine p50 %6.3f ms  p95 %6.3f ms  max %6.3f ms | pick p50 %6.3f ms  p95 %6.3f ms"
                " | operations p50 %5.0f\n",
                what, s.engine_ms.size(), percentile(s.engine_ms, 0.5), percentile(s.engine_ms, 0.95),
                percentile(s.engine_ms, 1.0), percentile(s.pick_ms, 0.5), percentile(s.pick_ms, 0.95),
                percentile(s.operations, 0.5));
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<int> levels;
    for (int i = 1; i < argc; ++i) levels.push_back(std::atoi(argv[i]));
    if (levels.empty()) levels = {3, 4};
    const std::string bunny = std::string(RGBSUB_SOURCE_DIR) + "/assets/bunny.obj";
    for (int level : levels) {
        rgb::Mesh mesh = rgbio::load_mesh(bunny);
        rgb::refine_uniform(mesh, level);
        std::printf("bunny at level %d: %zu triangles\n", level, mesh.num_faces());
        app::Editor editor(kViewport);
        editor.document().adopt(std::move(mesh), "");
        editor.reset_view();
        editor.brush().radius_px = 25.0f / std::exp2(static_cast<float>(level - 3));
        editor.brush().falloff = 0.3f;
        editor.brush().target_level = level + 1;
        report("refine one level deeper", replay(editor, {}));
        editor.brush().target_level = level;
        report("coarsen back (Shift)", replay(editor, {.shift = true}));
    }
    return 0;
}
